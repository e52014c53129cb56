"""Runs inside the ParaView GUI (paraview --script=...) for
RunRecolorTest.sh: loads the plugin and writes three LAS files into
GUI_TEST_WORK:
- tile.las: colored (the west half pure red, the east half pure green),
  classified ground (2) in the west half and building (6) in the east;
- zero.las: the same ground with Red, Green and Blue all 0 (fields never
  filled, as in many forest tiles);
- result.las: tile.las through Principal Curvatures, saved by the plugin's
  LAS writer (a saved result, colors and curvatures).
Then it writes a marker file, and from then on:
- after every render of the view, rewrites GUI_TEST_WORK/state: for each
  displayed file its coloring (array, Map Scalars) and whether a scalar bar
  shows for it;
- every 0.2 s, carries out GUI_TEST_WORK/request if there is one ("NAME
  color ARRAY" or "NAME hide") and removes it. Coloring goes through
  simple.ColorBy, the same change of the display's ColorArrayName as the
  toolbar's array box makes; Map Scalars is never set here.
The driver opens and applies the files through File > Open and Apply."""

import os
import sys

from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMPVRepresentationProxy, vtkSMTransferFunctionProxy

sys.path.insert(0, os.environ["GUI_TEST_SCRIPTS"])
from las_tiles import write_tile  # noqa: E402  (beside this script)

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]
WEST, SOUTH = 637000.0, 852000.0
READERS = ("ALASPointCloudReader",)


def ground_west_building_east(i, j, rows):
    return 2 if i < rows // 2 else 6


def all_zero(i, j, rows):
    return (0, 0, 0)


UTM = ('PROJCS["WGS 84 / UTM zone 33N",GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,'
       '298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433]],PROJECTION["Transverse_Mercator"],'
       'PARAMETER["central_meridian",15],PARAMETER["scale_factor",0.9996],PARAMETER["false_easting",500000],'
       'PARAMETER["false_northing",0],UNIT["metre",1],AUTHORITY["EPSG","32633"]]')


def write_inputs():
    tile = os.path.join(work, "tile.las")
    # In metres (a WKT record), with one point 30 m off the tile, alone:
    # not estimated.
    write_tile(tile, WEST, SOUTH, classes=ground_west_building_east, wkt=UTM,
               lone=(WEST + 230.0, SOUTH + 100.0, 50.0))
    write_tile(os.path.join(work, "zero.las"), WEST, SOUTH, colors=all_zero)
    reader = simple.OpenDataFile(tile)
    curvatures = simple.PrincipalCurvatures(Input=reader)
    simple.SaveData(os.path.join(work, "result.las"), proxy=curvatures)
    simple.Delete(curvatures)
    simple.Delete(reader)


def displayed_files(view):
    """(file name, source, display) of each visible display of a reader."""
    for _, source in sorted(simple.GetSources().items()):
        # servermanager's lookup: simple's would make a display.
        display = servermanager.GetRepresentation(source, view) if source.GetXMLName() in READERS else None
        if display is not None:
            yield os.path.basename(source.FileName), source, display


def bar_text(display, view):
    """" title <title> | nan <annotation>" of the display's color bar, if it
    has one (found, not made)."""
    lookup = display.LookupTable
    bar = vtkSMTransferFunctionProxy.FindScalarBarRepresentation(lookup.SMProxy, view.SMProxy) if lookup else None
    if bar is None:
        return ""
    helper = servermanager._getPyProxy(bar)
    nan = helper.NanAnnotation if helper.DrawNanAnnotation else "-"
    return " title %s | nan %s" % (helper.Title, nan)


def record_state(caller, event):
    """One line per visible display, after each render of the view."""
    try:
        view = simple.GetActiveView()
        lines = ["file %s colored_by %s map_scalars %d scalar_bar %d%s\n" % (
            name, display.ColorArrayName[1] or "-", display.MapScalars,
            vtkSMPVRepresentationProxy.IsScalarBarVisible(display.SMProxy, view.SMProxy), bar_text(display, view))
            for name, _, display in displayed_files(view) if display.Visibility]
        with open(os.path.join(work, "state"), "w") as handle:
            handle.writelines(lines)
    except Exception as error:  # the driver reports it
        with open(os.path.join(work, "state"), "w") as handle:
            handle.write("error %s\n" % error)


def carry_out_request(caller, event):
    path = os.path.join(work, "request")
    if not os.path.exists(path):
        return
    with open(path) as handle:
        words = handle.read().split()
    os.remove(path)
    view = simple.GetActiveView()
    for name, source, display in displayed_files(view):
        if name != words[0]:
            continue
        if words[1] == "color":
            simple.ColorBy(display, ("POINTS", words[2]))
        else:
            simple.Hide(source, view)
    simple.Render(view)


try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    write_inputs()
    view = simple.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    window = view.GetRenderWindow()
    window.AddObserver("EndEvent", record_state)
    interactor = window.GetInteractor()
    interactor.AddObserver("TimerEvent", carry_out_request)
    interactor.CreateRepeatingTimer(200)
    with open(marker, "w") as handle:
        handle.write("ready\n")
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
