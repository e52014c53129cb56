"""The tables of docs/settings.md, written from the one table of settings
(Core/Settings/SettingsTable.h, printed as JSON by PrintSettingsTable).

    build/bin/PrintSettingsTable > settings.json
    python3 Scripts/settings_table.py settings.json docs/settings.md          # rewrite
    python3 Scripts/settings_table.py settings.json docs/settings.md --check  # compare
    (TABLE - reads the JSON from standard input)

Each table sits between "<!-- settings: GROUP -->" and "<!-- end of
settings -->"; the text around them is left as it is. With --check, exits
with 1 and names the groups whose table differs (the SettingsAgree test).
"""

import argparse
import json
import re
import sys

BEGIN = re.compile(r"<!-- settings: (\w+) -->\n.*?<!-- end of settings -->", re.S)


def number(value):
    if value is None:
        return ""
    return ("%.15g" % value).replace("e+0", "e").replace("e+", "e")


def default_text(row):
    values = row["default"]
    if row["type"] == "bool":
        return "on" if values[0] else "off"
    if row["type"] == "enum":
        return row["choices"].split("|")[int(values[0])]
    return ", ".join(number(v) for v in values)


def range_text(row):
    if row["type"] in ("bool", "enum"):
        return " / ".join(row["choices"].split("|")) if row["type"] == "enum" else "on / off"
    low, high = row["minimum"], row["maximum"]
    if low is None and high is None:
        return "any"
    if high is None:
        return "at least %s" % number(low)
    return "%s to %s" % (number(low), number(high))


def table(rows, group):
    lines = ["| setting | default | range | unit | meaning |", "|---|---|---|---|---|"]
    for row in rows:
        if row["group"] != group:
            continue
        name = "`%s`" % row["name"]
        if row["normals_name"] and row["normals_name"] != row["name"]:
            name += " (Point Cloud Normals: `%s`)" % row["normals_name"]
        lines.append("| %s | %s | %s | %s | %s |" % (
            name, default_text(row), range_text(row), row["unit"], row["doc"]))
    return "\n".join(lines) + "\n"


def rewritten(text, rows):
    return BEGIN.sub(lambda m: "<!-- settings: %s -->\n%s<!-- end of settings -->" % (
        m.group(1), table(rows, m.group(1))), text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table")
    parser.add_argument("doc")
    parser.add_argument("--check", action="store_true")
    arguments = parser.parse_args()
    if arguments.table == "-":
        rows = json.load(sys.stdin)
    else:
        with open(arguments.table, encoding="utf-8") as handle:
            rows = json.load(handle)
    with open(arguments.doc, encoding="utf-8") as handle:
        text = handle.read()
    groups = set(BEGIN.findall(text))
    missing = sorted({row["group"] for row in rows} - groups)
    new = rewritten(text, rows)
    if arguments.check:
        stale = [g for g in sorted(groups)
                 if re.search(r"<!-- settings: %s -->\n(.*?)<!-- end" % g, text, re.S).group(1) != table(rows, g)]
        for group in stale:
            print("FAILED  docs table %s differs from the settings table (rerun Scripts/settings_table.py)" % group)
        for group in missing:
            print("FAILED  docs have no table for group %s" % group)
        if not stale and not missing:
            print("ok      docs/settings.md's %d tables are the settings table's" % len(groups))
        return 1 if stale or missing else 0
    with open(arguments.doc, "w", encoding="utf-8") as handle:
        handle.write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
