"""Runs inside the ParaView GUI (paraview --script=...) for
RunHelpTest.sh: loads the plugin, creates Principal Curvatures on a small
sphere and makes it the active source, so that the Properties panel shows
it (and its "?" asks for its help), then writes a marker file when the
GUI is ready for the click."""

import os

from paraview import simple

marker = os.environ["GUI_TEST_MARKER"]
try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    sphere = simple.Sphere(ThetaResolution=16, PhiResolution=16)
    sphere.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=sphere)
    simple.SetActiveSource(curvatures)
    with open(marker, "w") as handle:
        handle.write("ready %s\n" % curvatures.GetXMLName())
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
