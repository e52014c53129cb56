"""Runs inside the ParaView GUI (paraview --script=...): loads the plugin,
opens a cloud as File > Open would (OpenDataFile: a normals-less .xyz goes
to the plugin's text reader), applies Principal Curvatures with its
defaults (the normals are estimated), shows it as a first Apply does (no
representation, point size or coloring set here), and writes a marker
file with what it found (read by RunGuiTest.sh)."""

import os

from paraview import servermanager
from paraview.simple import (GetActiveViewOrCreate, Hide,
                             LoadPlugin, Render, ResetCamera, SetActiveSource, Show)
from paraview import simple

marker = os.environ["GUI_TEST_MARKER"]
try:
    LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    cloud = simple.OpenDataFile(os.environ["GUI_TEST_CLOUD"])
    cloud.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=cloud)
    SetActiveSource(curvatures)  # its properties fill the Properties panel
    view = GetActiveViewOrCreate("RenderView")
    display = Show(curvatures, view)
    Hide(cloud, view)
    # No ColorBy, no representation, no rescaling: the plugin's hint makes
    # it Points, and the active scalars (Mean_Curvature_Clipped) color it
    # over their robust range.
    colored_by = list(display.ColorArrayName)
    lookup = display.LookupTable  # the display's own (the plugin's GUI part)
    color_range = (lookup.RGBPoints[0], lookup.RGBPoints[-4])
    display.SetScalarBarVisibility(view, True)
    bar_title = simple.GetScalarBar(lookup, view).Title
    view.CameraPosition = [6, -9, 8]
    view.CameraViewUp = [0, 0, 1]
    ResetCamera(view)
    Render(view)
    output = servermanager.Fetch(curvatures)
    mean = output.GetPointData().GetArray("Mean_Curvature").GetRange()
    valid = output.GetPointData().GetArray("Curvature_Valid").GetRange()
    estimated = output.GetPointData().GetNormals() is not None
    with open(marker, "w") as handle:
        handle.write("ok reader %s, normals estimated %s, colored by %s, representation %s, point size %g, "
                     "color range %g %g, mean curvature %g %g, valid %g %g, color bar '%s'\n"
                     % (cloud.GetXMLName(), estimated, colored_by[-1], display.Representation,
                        display.PointSize, color_range[0], color_range[1], mean[0], mean[1], valid[0], valid[1],
                        bar_title))
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
