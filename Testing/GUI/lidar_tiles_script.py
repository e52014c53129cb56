"""Runs inside the ParaView GUI (paraview --script=...) for
RunLidarTilesTest.sh: loads the plugin, writes two colored LAS tiles 5 km
apart into GUI_TEST_WORK (LAS 1.2, point format 2, 16-bit colors: the west
half of each tile pure red, the east half pure green), writes a marker file
when the GUI is ready for keys, and from then on, after every render of the
view, rewrites GUI_TEST_WORK/state: for each displayed tile whether it lies
wholly in the view, its coloring (array, Map Scalars) and whether a scalar
bar shows for it. The driver opens and applies the tiles through File >
Open and the Apply button."""

import os
import sys

from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMPVRepresentationProxy

sys.path.insert(0, os.environ["GUI_TEST_SCRIPTS"])
from las_tiles import write_tile  # noqa: E402  (beside this script)

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]
EAST_OF_FIRST = 5000.0


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
