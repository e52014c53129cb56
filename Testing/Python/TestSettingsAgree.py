"""The settings are defined once, in the table of Core/Settings/SettingsTable.h
(printed as JSON by PrintSettingsTable); the core's settings take their
defaults from it, and the filters theirs from the core's. Checked here:

- each filter's defaults, and its clamps, are the table's;
- docs/settings.md's tables are the table's (Scripts/settings_table.py);
- the command-line tool sets no default of its own;
- every default_values of the plugin XML equals the filter's default;
- the XML's enumerations equal the filter's enum constants;
- the XML's ranges (the panel's sliders) start at the filter's clamp minimum
  and end within its clamp maximum (a slider spans typical values; a typed
  larger one is kept and clamped by the filter);
- the command-line tool's --dynamic-adjustment table equals the presets;
- the XML's documentation quotes the banded ladder's switch lengths.
- render_principal_directions.py defaults to the filter's fit and takes every
  fit mode; no document calls another fit the default.

    pvpython TestSettingsAgree.py PLUGIN.xml estimate_curvatures.py PrintSettingsTable SOURCE
(with the wrapped package on PYTHONPATH)
"""

import importlib.util
import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

from principal_curvatures import vtkPointCloudNormalEstimation, vtkPrincipalCurvatureEstimation

xml_path, cli_path, table_printer, source = sys.argv[1:5]
failures = []


def check(condition, message):
    print(("ok      " if condition else "FAILED  ") + message)
    if not condition:
        failures.append(message)


def as_list(value):
    return [float(v) for v in value] if isinstance(value, (tuple, list)) else [float(value)]


# The table against each filter's defaults and clamps.
rows = json.loads(subprocess.check_output([table_printer]).decode())
check(len(rows) >= 25, "%d settings in the table" % len(rows))
for row in rows:
    for make, name in ((vtkPrincipalCurvatureEstimation, row["name"]),
                       (vtkPointCloudNormalEstimation, row["normals_name"])):
        if name is None:
            continue
        check(as_list(getattr(make(), "Get" + name)()) == row["default"],
              "%s.%s: default %s, table %s" % (make.__name__, name, getattr(make(), "Get" + name)(), row["default"]))
        if row["type"] not in ("int", "double", "enum"):
            continue
        for bound, beyond in (("minimum", -1.0), ("maximum", 1.0)):
            limit = row[bound]
            if limit is None:
                continue
            probe = make()
            value = limit + beyond * max(1.0, abs(limit))
            getattr(probe, "Set" + name)(int(value) if row["type"] != "double" else value)
            check(float(getattr(probe, "Get" + name)()) == limit,
                  "%s.%s: clamped to the table's %s %s" % (make.__name__, name, bound, limit))

# The docs' tables.
sys.path.insert(0, os.path.join(source, "Scripts"))
import settings_table  # noqa: E402

with open(os.path.join(source, "docs", "settings.md"), encoding="utf-8") as handle:
    settings_doc = handle.read()
check(settings_table.rewritten(settings_doc, rows) == settings_doc,
      "docs/settings.md's tables are written from the table (else run Scripts/settings_table.py)")
check(set(settings_table.BEGIN.findall(settings_doc)) == {row["group"] for row in rows},
      "docs/settings.md has a table for every group of settings")


def values(text, kind):
    return [kind(v) for v in text.split()]


import principal_curvatures

checked = 0
for proxy in ElementTree.parse(xml_path).iter("SourceProxy"):
    cls = getattr(principal_curvatures, proxy.get("class"), None)
    if cls is None:
        continue
    defaults = cls()
    for prop in proxy:
        command = prop.get("command") or ""
        if not command.startswith("Set") or prop.get("default_values") is None:
            continue
        getter = getattr(defaults, "Get" + command[3:], None)
        if getter is None:
            continue
        kind = float if prop.tag == "DoubleVectorProperty" else int
        expected = getter()
        expected = list(expected) if isinstance(expected, tuple) else [expected]
        given = values(prop.get("default_values"), kind)
        check([kind(v) for v in expected] == given, "%s.%s: XML default %s, filter default %s" % (
            proxy.get("name"), prop.get("name"), given, expected))
        checked += 1
        for domain in prop:
            if domain.tag in ("IntRangeDomain", "DoubleRangeDomain"):
                for end in ("min", "max"):
                    clamp = getattr(defaults, "Get%s%sValue" % (command[3:], end.capitalize()), None)
                    if domain.get(end) is not None and clamp is not None:
                        given, limit = kind(domain.get(end)), kind(clamp())
                        check(given == limit if end == "min" else given <= limit,
                              "%s.%s: XML %s %s, clamp %s" % (
                                  proxy.get("name"), prop.get("name"), end, domain.get(end), clamp()))
check(checked >= 25, "%d XML defaults compared" % checked)

filter_defaults = vtkPrincipalCurvatureEstimation()
proxy = next(p for p in ElementTree.parse(xml_path).iter("SourceProxy")
             if p.get("class") == "vtkPrincipalCurvatureEstimation")
enumerations = {
    "FitMode": {"Previous": filter_defaults.PREVIOUS, "New01": filter_defaults.NEW01,
                "New02": filter_defaults.NEW02, "OrientedCircles": filter_defaults.ORIENTED_CIRCLES},
    "NeighborhoodMode": {"Radius": filter_defaults.RADIUS, "K Nearest": filter_defaults.K_NEAREST,
                         "Automatic": filter_defaults.AUTOMATIC_SCALE},
    "NormalsSource": {"Automatic": filter_defaults.AUTOMATIC_NORMALS,
                      "Input Array": filter_defaults.INPUT_NORMALS,
                      "Estimated": filter_defaults.ESTIMATED_NORMALS},
    "NormalOrientation": {"Outward": filter_defaults.OUTWARD,
                          "Towards Viewpoint": filter_defaults.TOWARDS_VIEWPOINT,
                          "Along Axis": filter_defaults.ALONG_AXIS},
}
for prop in proxy:
    if prop.get("name") in enumerations:
        entries = {e.get("text"): int(e.get("value")) for e in prop.iter("Entry")}
        check(entries == enumerations[prop.get("name")],
              "%s: XML entries %s" % (prop.get("name"), entries))

spec = importlib.util.spec_from_file_location("estimate_curvatures", cli_path)
cli = importlib.util.module_from_spec(spec)
spec.loader.exec_module(cli)
presets = {"paper": filter_defaults.PAPER_CONSTANTS, "ladder": filter_defaults.LADDER,
           "noisy-ladder": filter_defaults.NOISY_LADDER}
check(sorted(cli.ADJUSTMENTS) == sorted(presets), "the tool's adjustment names: %s" % sorted(cli.ADJUSTMENTS))
for name, preset in presets.items():
    f = vtkPrincipalCurvatureEstimation()
    f.SetAdjustmentConstantsToPreset(preset)
    unset = vtkPrincipalCurvatureEstimation()
    for setting in ("TargetNeighborCounts", "TargetPlaneDistances", "SwitchLengths"):
        given = cli.ADJUSTMENTS.get(name, {}).get(setting, list(getattr(unset, "Get" + setting)()))
        expected = list(getattr(f, "Get" + setting)())
        check([float(v) for v in given] == expected,
              "--dynamic-adjustment %s: %s %s, filter preset %s" % (name, setting, given, expected))
# The tool leaves every setting it is not given at the filter's default.
given = cli.parse_arguments(["in.vtp", "out.vtp"])
settings_options = ("orientation", "viewpoint", "axis", "threads", "neighbors", "radius", "plane_distance")
check(all(getattr(given, option) is None for option in settings_options),
      "the tool sets no default of its own for %s" % ", ".join("--" + o for o in settings_options))

ladder = vtkPrincipalCurvatureEstimation()
ladder.SetAdjustmentConstantsToPreset(ladder.LADDER)
switches = " ".join("%g" % v for v in ladder.GetSwitchLengths())
documentation = " ".join(" ".join(d.text.split()) for d in proxy.iter("Documentation") if d.text)
check(switches in documentation, "the XML documentation quotes the ladder's switch lengths %s" % switches)

# The default fit as the tools and the documentation state it.
import os
import re

fit_names = {int(e.get("value")): e.get("text")
             for p in proxy if p.get("name") == "FitMode" for e in p.iter("Entry")}
default_fit = fit_names[vtkPrincipalCurvatureEstimation().GetFitMode()]
render_path = os.path.join(os.path.dirname(cli_path), "render_principal_directions.py")
spec = importlib.util.spec_from_file_location("render_principal_directions", render_path)
render = importlib.util.module_from_spec(spec)
spec.loader.exec_module(render)
rendered = render.parse_arguments(["in.vtp", "out.png"])
check(rendered.fit_mode == default_fit, "render_principal_directions.py: default --fit-mode %s (the filter's %s)"
      % (rendered.fit_mode, default_fit))
check(sorted(render.parse_arguments(["a", "b", "--fit-mode", name]).fit_mode for name in fit_names.values())
      == sorted(fit_names.values()), "render_principal_directions.py: --fit-mode takes %s"
      % " ".join(sorted(fit_names.values())))
# Stale claims that another fit is the default ("Default fit mode New01",
# "SetFitModeToNew01(); // the default", "New01 (the default)").
repository = os.path.dirname(os.path.dirname(os.path.abspath(cli_path)))
documents = [os.path.join(repository, "README.md")] + [
    os.path.join(repository, "docs", name) for name in sorted(os.listdir(os.path.join(repository, "docs")))
    if name.endswith(".md")]
for name in (n for n in fit_names.values() if n != default_fit):
    claim = re.compile(r"default fit mode:?\s+\**%s\b|%s\b[^.]*\bthe default\b" % (name, name), re.IGNORECASE)
    stale = ["%s:%d" % (os.path.relpath(path, repository), number)
             for path in documents for number, line in enumerate(open(path), 1) if claim.search(line)]
    check(not stale, "no document calls %s the default (%s)" % (name, " ".join(stale) or "none"))

print("%d failed" % len(failures))
sys.exit(1 if failures else 0)
