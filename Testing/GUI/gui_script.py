"""Runs inside the ParaView GUI (paraview --script=...): loads the plugin,
applies Principal Curvatures to a cloud, colours by Mean_Curvature, and
writes a marker file with what it found (read by RunGuiTest.sh)."""

import os

from paraview import servermanager
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction, Hide,
                             LoadPlugin, Render, ResetCamera, SetActiveSource, Show,
                             XMLPolyDataReader)
from paraview import simple

marker = os.environ["GUI_TEST_MARKER"]
try:
    LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    cloud = XMLPolyDataReader(FileName=[os.environ["GUI_TEST_CLOUD"]])
    cloud.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=cloud)
    SetActiveSource(curvatures)  # its properties fill the Properties panel
    view = GetActiveViewOrCreate("RenderView")
    display = Show(curvatures, view)
    display.PointSize = 3
    Hide(cloud, view)
    ColorBy(display, ("POINTS", "Mean_Curvature"))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    view.CameraPosition = [6, -9, 8]
    view.CameraViewUp = [0, 0, 1]
    ResetCamera(view)
    Render(view)
    mean = servermanager.Fetch(curvatures).GetPointData().GetArray("Mean_Curvature").GetRange()
    with open(marker, "w") as handle:
        handle.write("ok %g %g\n" % mean)
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
