"""The plugin's Qt help (.qch, an SQLite file) holds the pages that the
"?" of its filters, readers and writers open: ParaView 5.11's
pqHelpReaction::showProxyHelp looks for qthelp://<namespace>/<folder>/
<group>.<proxy>.html in every registered help namespace. Checks that there
is a page for every proxy of Plugin/*.xml; that the filter's page has its
picture, the sign convention and every output array that
docs/output-arrays.md lists; and that the filter's short help does not say
that normals are required.
    python3 TestHelpPages.py PLUGIN.qch SOURCE_DIR"""

import glob
import os
import re
import sqlite3
import sys
import xml.etree.ElementTree as ElementTree
import zlib

NAMESPACE = "PrincipalCurvatures.org"
FILTER_PAGE = "filters.PrincipalCurvatureEstimation.html"
# The proxy elements ParaView's paraview_servermanager_convert_xml.xsl makes pages of.
PROXY_TAGS = ("CompoundSourceProxy", "SourceProxy", "Proxy", "PWriterProxy", "WriterProxy", "PSWriterProxy")


def help_files(qch_path):
    """{file name: bytes} of the help's files (qCompress: 4-byte length, zlib)."""
    connection = sqlite3.connect(qch_path)
    namespaces = [row[0] for row in connection.execute("SELECT Name FROM NamespaceTable")]
    rows = connection.execute(
        "SELECT FileNameTable.Name, FileDataTable.Data FROM FileNameTable "
        "JOIN FileDataTable ON FileNameTable.FileId = FileDataTable.Id")
    files = {name: zlib.decompress(bytes(data)[4:]) for name, data in rows if name and data}
    connection.close()
    return namespaces, files


def plugin_proxies(source_dir):
    """(group, name, element) of every proxy in the plugin's server-manager XML."""
    proxies = []
    for path in sorted(glob.glob(os.path.join(source_dir, "Plugin", "*.xml"))):
        for group in ElementTree.parse(path).getroot().iter("ProxyGroup"):
            for element in group:
                # Internal groups (a parallel writer's inner writer) are
                # never shown in the GUI, and ParaView makes no page of them.
                if element.tag in PROXY_TAGS and not group.get("name").startswith("internal_"):
                    proxies.append((group.get("name"), element.get("name"), element))
    return proxies


def documented_arrays(source_dir):
    """The array names of the tables in docs/output-arrays.md (first column, in backquotes)."""
    names = set()
    with open(os.path.join(source_dir, "docs", "output-arrays.md"), encoding="utf-8") as table:
        for line in table:
            if line.startswith("| `"):
                first_column = line.split("|")[1]
                names.update(re.findall(r"`([A-Za-z_]+)`", first_column))
    return sorted(names)


def main(qch_path, source_dir):
    if not os.path.isfile(qch_path):
        print("FAILED: no help file %s (built without its help pages?)" % qch_path)
        return 1
    failures = []
    namespaces, files = help_files(qch_path)
    if NAMESPACE not in namespaces:
        failures.append("namespace %s not in %s" % (NAMESPACE, namespaces))
    proxies = plugin_proxies(source_dir)
    for group, name, _ in proxies:
        page = "%s.%s.html" % (group, name)
        print("page %s: %s" % (page, "present" if page in files else "MISSING"))
        if page not in files:
            failures.append("no help page %s" % page)
    filter_page = files.get(FILTER_PAGE, b"").decode("utf-8", "replace")
    picture = re.search(r'<img src="([^"]+)"', filter_page)
    if not picture or picture.group(1) not in files:
        failures.append("the filter's page shows no picture held in the help")
    for heading in ("Sign convention", "Output arrays", "bends away from the normal"):
        if heading not in filter_page:
            failures.append("the filter's page has no '%s'" % heading)
    arrays = documented_arrays(source_dir)
    missing = [name for name in arrays if name not in filter_page]
    print("output arrays in docs/output-arrays.md: %d, missing from the filter's page: %s" % (len(arrays), missing))
    if len(arrays) < 20 or missing:
        failures.append("output arrays missing from the filter's page: %s" % missing)
    for group, name, element in proxies:
        documentation = element.find("Documentation")
        short_help = documentation.get("short_help", "") if documentation is not None else ""
        if group == "filters" and re.search(r"\bwith normals\b", short_help):
            failures.append("%s's short help says normals are required: %r" % (name, short_help))
    for failure in failures:
        print("FAILED: " + failure)
    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
