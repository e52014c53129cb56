"""Runs inside the ParaView GUI (paraview --script=...) for
RunQuickLaunchTest.sh: loads the plugin, opens a cloud with normals (so
that ParaView's Principal Component Analysis filter is enabled too), shows
it, makes it the active source (the quick launch creates filters on the
active source) and writes a marker file when the GUI is ready for keys."""

import os

from paraview import simple

marker = os.environ["GUI_TEST_MARKER"]
try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    cloud = simple.OpenDataFile(os.environ["GUI_TEST_CLOUD"])
    cloud.UpdatePipeline()
    simple.Show(cloud)
    simple.SetActiveSource(cloud)
    simple.Render()
    with open(marker, "w") as handle:
        handle.write("ready %s, point arrays %s\n" % (cloud.GetXMLName(), " ".join(cloud.PointData.keys())))
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
