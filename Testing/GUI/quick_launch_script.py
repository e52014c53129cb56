"""Runs inside the ParaView GUI (paraview --script=...) for
RunQuickLaunchTest.sh: loads the plugin; opens bad text clouds as File >
Open does (OpenDataFile: ParaView 5.11 gave them to the PLOT3D reader, and
Apply crashed the GUI), shows and deletes them; opens a cloud with normals
(so that ParaView's Principal Component Analysis filter is enabled too),
shows it, makes it the active source (the quick launch creates filters on
the active source) and writes a marker file when the GUI is ready for
keys."""

import os
import shutil
import tempfile

from paraview import simple

marker = os.environ["GUI_TEST_MARKER"]
try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    readers = []
    folder = tempfile.mkdtemp(prefix="gui_bad_")
    for name, text in (("empty.xyz", ""), ("flat.xyz", "1 2\n3 4\n"), ("words.xyz", "hello world\nfoo bar\n")):
        path = os.path.join(folder, name)
        with open(path, "w") as handle:
            handle.write(text)
        bad = simple.OpenDataFile(path)
        readers.append(bad.GetXMLName())
        simple.Show(bad)  # what Apply does: update and show
        simple.Render()
        simple.Delete(bad)
    shutil.rmtree(folder, ignore_errors=True)
    cloud = simple.OpenDataFile(os.environ["GUI_TEST_CLOUD"])
    cloud.UpdatePipeline()
    simple.Show(cloud)
    simple.SetActiveSource(cloud)
    simple.Render()
    with open(marker, "w") as handle:
        handle.write("ready %s, point arrays %s, bad files read by %s\n"
                     % (cloud.GetXMLName(), " ".join(cloud.PointData.keys()), " ".join(readers)))
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
