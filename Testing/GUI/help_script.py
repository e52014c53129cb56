"""Runs inside the ParaView GUI (paraview --script=...) for
RunHelpTest.sh: loads the plugin, creates Principal Curvatures on a small
cloud without normals and makes it the active source, so that the
Properties panel shows it (its Normals row reading "None (automatic)",
and its "?" asking for its help), then writes a marker file when the GUI
is ready for the click."""

import os

from paraview import simple

marker = os.environ["GUI_TEST_MARKER"]
try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    cloud = simple.PointSource(NumberOfPoints=400, Radius=1.0)
    cloud.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=cloud)
    simple.SetActiveSource(curvatures)
    with open(marker, "w") as handle:
        handle.write("ready %s\n" % curvatures.GetXMLName())
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
