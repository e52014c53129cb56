"""Runs inside the ParaView GUI (paraview --script=...), driven by
RunColorMapTest.sh: one session, three tori of very different scales
(minor radius 0.1, 10 and 1000: curvatures from about 10 down to 0.001),
written as text clouds with normals and opened as File > Open would
(OpenDataFile), each applied Principal Curvatures and shown as the GUI's
Apply shows a new output: Show (the same pipeline controller), then every
color map's range updated from the visible data as pqApplyBehavior does
(by default growing it), side by side in three views. Writes
GUI_TEST_MARKER: for each cloud the range of its display's color map and
of its Mean_Curvature_Clipped."""

import os

import numpy
from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMTransferFunctionManager

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]


def write_torus(path, scale, count=20000, seed=5):
    """A torus (radii 1.5 and 1, times `scale`) with its exact outward normals: its
    mean curvature is negative on the inner side (the ring radius is below twice
    the tube's), so a map centered on zero shows both of its ends."""
    generator = numpy.random.default_rng(seed)
    u, v = generator.uniform(0.0, 2.0 * numpy.pi, (2, count))
    ring = 1.5 + numpy.cos(v)
    points = scale * numpy.column_stack([ring * numpy.cos(u), ring * numpy.sin(u), numpy.sin(v)])
    normals = numpy.column_stack([numpy.cos(v) * numpy.cos(u), numpy.cos(v) * numpy.sin(u), numpy.sin(v)])
    numpy.savetxt(path, numpy.hstack([points, normals]), fmt="%.9g")


def show_in_new_view(curvatures, first_view):
    """The first cloud in the GUI's view, the others each in a view of their own."""
    if first_view is not None:
        view = simple.CreateView("RenderView")
        simple.AssignViewToLayout(view=view)
    else:
        view = simple.GetActiveViewOrCreate("RenderView")
    simple.SetActiveView(view)
    display = simple.Show(curvatures, view)
    view.OrientationAxesVisibility = 0
    view.CameraPosition = [0, -1, 1.2]
    view.CameraViewUp = [0, 0, 1]
    simple.ResetCamera(view)
    return view, display


try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    lines = []
    first_view = None
    for name, scale in (("small", 0.1), ("large", 10.0), ("huge", 1000.0)):
        path = os.path.join(work, "torus_%s.xyz" % name)
        write_torus(path, scale)
        cloud = simple.OpenDataFile(path)
        cloud.UpdatePipeline()
        curvatures = simple.PrincipalCurvatures(Input=cloud)
        simple.SetActiveSource(curvatures)
        view, display = show_in_new_view(curvatures, first_view)
        first_view = first_view or view
        vtkSMTransferFunctionManager().ResetAllTransferFunctionRangesUsingCurrentData(
            servermanager.ProxyManager().SMProxyManager, False)
        simple.Render(view)
        color_map = display.LookupTable
        points = color_map.RGBPoints
        clipped = servermanager.Fetch(curvatures).GetPointData().GetArray("Mean_Curvature_Clipped").GetRange()
        lines.append("cloud %s scale %g colored by %s map %s range %.9g %.9g data %.9g %.9g"
                     % (name, scale, display.ColorArrayName[1], color_map.GetXMLName() and color_map.SMProxy.GetGlobalIDAsString(),
                        points[0], points[-4], clipped[0], clipped[1]))
    with open(marker, "w") as handle:
        handle.write("ok\n" + "\n".join(lines) + "\n")
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
