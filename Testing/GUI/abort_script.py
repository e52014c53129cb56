"""Runs inside the ParaView GUI (paraview --script=...), driven by
RunAbortTest.sh: loads the plugin, makes a 3M-point torus without normals
(a run of about 15 s on two cores with shared fits), applies Principal Curvatures to it
as the active source, and runs it. Before the run it writes
GUI_TEST_MARKER.running; after, GUI_TEST_MARKER with when the run returned
(time.time()), how long it took, the largest progress short of 1 the filter
reported (how far the run got before it stopped) and how many points the
output has."""

import os
import time

import numpy
from paraview import simple
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

marker = os.environ["GUI_TEST_MARKER"]


def torus(count=3000000, seed=23):
    generator = numpy.random.default_rng(seed)
    u, v = generator.uniform(0.0, 2.0 * numpy.pi, (2, count))
    ring = 3.0 + numpy.cos(v)
    return numpy.column_stack([ring * numpy.cos(u), ring * numpy.sin(u), numpy.sin(v)])


try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    cloud = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(torus(), deep=True))
    cloud.SetPoints(points)
    source = simple.TrivialProducer()
    source.GetClientSideObject().SetOutput(cloud)
    source.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=source)
    simple.SetActiveSource(curvatures)
    reached = [0.0]

    def on_progress(algorithm, _event):
        if algorithm.GetProgress() < 1.0:
            reached[0] = max(reached[0], algorithm.GetProgress())

    curvatures.GetClientSideObject().AddObserver("ProgressEvent", on_progress)
    with open(marker + ".running", "w") as handle:
        handle.write("%.6f\n" % time.time())
    start = time.time()
    curvatures.UpdatePipeline()
    returned = time.time()
    with open(marker, "w") as handle:
        handle.write("ok returned %.6f after %.2f s, reached %.4f, output points %d\n"
                     % (returned, returned - start, reached[0],
                        curvatures.GetDataInformation().GetNumberOfPoints()))
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
