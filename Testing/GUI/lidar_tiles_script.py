"""Runs inside the ParaView GUI (paraview --script=...) for
RunLidarTilesTest.sh: loads the plugin, writes two colored LAS tiles 5 km
apart into GUI_TEST_WORK (LAS 1.2, point format 2, 16-bit colors: the west
half of each tile pure red, the east half pure green), writes a marker file
when the GUI is ready for keys, and from then on, after every render of the
view, rewrites GUI_TEST_WORK/state: for each displayed tile whether it lies
wholly in the view, its coloring (array, Map Scalars) and whether a scalar
bar shows for it. The driver opens and applies the tiles through File >
Open and the Apply button."""

import math
import os
import struct

from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMPVRepresentationProxy

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]
EAST_OF_FIRST = 5000.0


def tile_points(west, south, size=200.0, rows=60):
    """A gently rolling 200 m square of ground (no random numbers), with its colors."""
    for i in range(rows):
        for j in range(rows):
            x, y = west + size * (i + 0.5) / rows, south + size * (j + 0.5) / rows
            z = 50.0 + 3.0 * math.sin(i / 7.0) * math.cos(j / 9.0)
            red = i < rows // 2
            yield (x, y, z), (65535, 0, 0) if red else (0, 65535, 0)


def write_tile(path, west, south, scale=0.01):
    """LAS 1.2, point format 2 (26-byte records: format 0 and Red, Green, Blue)."""
    points = list(tile_points(west, south))
    xyz = [p for p, _ in points]
    header = bytearray(227)
    header[0:4] = b"LASF"
    header[24], header[25] = 1, 2
    struct.pack_into("<HIIBHI", header, 94, 227, 227, 0, 2, 26, len(points))
    offset = (west, south, 0.0)
    struct.pack_into("<3d3d", header, 131, scale, scale, scale, *offset)
    low = [min(p[k] for p in xyz) for k in range(3)]
    high = [max(p[k] for p in xyz) for k in range(3)]
    struct.pack_into("<6d", header, 179, high[0], low[0], high[1], low[1], high[2], low[2])
    records = b"".join(
        struct.pack("<3iHBBbBH3H", *(round((c - o) / scale) for c, o in zip(p, offset)), 0, 0x09, 2, 0, 0, 0, *rgb)
        for p, rgb in points)
    with open(path, "wb") as handle:
        handle.write(bytes(header) + records)


def wholly_in_view(view, bounds):
    """Every corner of bounds projects inside the view's window."""
    width, height = view.ViewSize
    matrix = view.GetActiveCamera().GetCompositeProjectionTransformMatrix(width / float(height), -1, 1)
    for corner in range(8):
        point = (bounds[corner & 1], bounds[2 + ((corner >> 1) & 1)], bounds[4 + ((corner >> 2) & 1)], 1.0)
        x, y, _, w = matrix.MultiplyPoint(point)
        if w <= 0 or abs(x) > w or abs(y) > w:
            return False
    return True


def record_state(caller, event):
    """One line per displayed tile, after each render of the view."""
    try:
        view = simple.GetActiveView()
        lines = []
        for name, source in sorted(simple.GetSources().items()):
            # servermanager's lookup: simple's would make a display.
            display = servermanager.GetRepresentation(source, view) if source.GetXMLName() == "ALASPointCloudReader" else None
            if display is None or not display.Visibility:
                continue
            bounds = source.GetDataInformation().GetBounds()
            lines.append("tile %s in_view %d colored_by %s map_scalars %d scalar_bar %d\n" % (
                os.path.basename(source.FileName), wholly_in_view(view, bounds), display.ColorArrayName[1] or "-",
                display.MapScalars, vtkSMPVRepresentationProxy.IsScalarBarVisible(display.SMProxy, view.SMProxy)))
        with open(os.path.join(work, "state"), "w") as handle:
            handle.writelines(lines)
    except Exception as error:  # the driver reports it
        with open(os.path.join(work, "state"), "w") as handle:
            handle.write("error %s\n" % error)


try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    write_tile(os.path.join(work, "tile_west.las"), 637000.0, 852000.0)
    write_tile(os.path.join(work, "tile_east.las"), 637000.0 + EAST_OF_FIRST, 852000.0)
    view = simple.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    view.GetRenderWindow().AddObserver("EndEvent", record_state)
    with open(marker, "w") as handle:
        handle.write("ready\n")
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
