"""Runs inside the ParaView GUI (paraview --script=...) for
RunFileOpenTest.sh: loads the plugin (whose GUI part makes its readers
File > Open's defaults for point cloud files), writes a text cloud as .xyz
as .pts and as .las into GUI_TEST_WORK, and writes a marker file when the GUI is
ready for keys. While the GUI runs, every proxy registration (File >
Open's reader among them) rewrites GUI_TEST_WORK/sources: one line per
source, its proxy name and file."""

import math
import os
import struct

from paraview import servermanager, simple

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]


def sphere_points(count=500):
    """Points on a unit sphere (a Fibonacci spiral: no random numbers)."""
    golden = math.pi * (3.0 - math.sqrt(5.0))
    for i in range(count):
        z = 1.0 - 2.0 * (i + 0.5) / count
        r = math.sqrt(1.0 - z * z)
        yield r * math.cos(golden * i), r * math.sin(golden * i), z


def record_sources(caller, event):
    """The sources there are now (called by the proxy manager as the GUI registers proxies)."""
    lines = []
    for source in simple.GetSources().values():
        file_name = source.GetProperty("FileName")
        lines.append("%s %s\n" % (source.GetXMLName(), file_name.GetElement(0) if file_name else "-"))
    with open(os.path.join(work, "sources"), "w") as handle:
        handle.writelines(sorted(lines))


def write_las(path, points, scale=1e-3):
    """LAS 1.2, point format 0 (20-byte records), no variable-length records."""
    header = bytearray(227)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 2
    struct.pack_into("<HIIBHI", header, 94, 227, 227, 0, 0, 20, len(points))
    struct.pack_into("<3d3d", header, 131, scale, scale, scale, 0.0, 0.0, 0.0)
    struct.pack_into("<6d", header, 179, 1, -1, 1, -1, 1, -1)
    records = b"".join(struct.pack("<3iHBBbBH", *(round(c / scale) for c in point), 0, 0x09, 2, 0, 0, 0)
                       for point in points)
    with open(path, "wb") as handle:
        handle.write(bytes(header) + records)


try:
    observer = servermanager.ProxyManager().SMProxyManager.AddObserver("RegisterEvent", record_sources)
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    points = list(sphere_points())
    with open(os.path.join(work, "scan.xyz"), "w") as handle:
        handle.writelines("%.9g %.9g %.9g\n" % point for point in points)
    with open(os.path.join(work, "scan.pts"), "w") as handle:
        handle.write("%d\n" % len(points))
        handle.writelines("%.9g %.9g %.9g 100 10 20 30\n" % point for point in points)
    write_las(os.path.join(work, "scan.las"), points)
    with open(marker, "w") as handle:
        handle.write("ready\n")
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
