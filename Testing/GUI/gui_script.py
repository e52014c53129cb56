"""Runs inside the ParaView GUI (paraview --script=...): loads the plugin,
opens a cloud as File > Open would (OpenDataFile: a normals-less .xyz goes
to the plugin's text reader), applies Principal Curvatures with its
defaults (the normals are estimated), colours by Mean_Curvature, and writes
a marker file with what it found (read by RunGuiTest.sh)."""

import os

from paraview import servermanager
from paraview.simple import (GetActiveViewOrCreate, GetColorTransferFunction, Hide,
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
    display.PointSize = 3
    Hide(cloud, view)
    # No ColorBy: the filter's output makes Mean_Curvature the active
    # scalars, which ParaView colours a new display by.
    coloured_by = list(display.ColorArrayName)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [6, -9, 8]
    view.CameraViewUp = [0, 0, 1]
    ResetCamera(view)
    Render(view)
    output = servermanager.Fetch(curvatures)
    mean = output.GetPointData().GetArray("Mean_Curvature").GetRange()
    valid = output.GetPointData().GetArray("Curvature_Valid").GetRange()
    estimated = output.GetPointData().GetNormals() is not None
    with open(marker, "w") as handle:
        handle.write("ok reader %s, normals estimated %s, coloured by %s, mean curvature %g %g, valid %g %g\n"
                     % (cloud.GetXMLName(), estimated, coloured_by[-1], mean[0], mean[1], valid[0], valid[1]))
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
