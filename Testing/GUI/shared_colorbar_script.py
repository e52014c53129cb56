"""Runs inside the ParaView GUI (paraview --script=...), driven by
RunSharedColorBarTest.sh: two tori of different sizes (minor radius 1 and
2: mean curvatures a factor 2 apart), each read as File > Open would
(OpenDataFile), applied Principal Curvatures and shown in the same view as
the GUI's Apply shows a new output (Show, the scalar bar shown, every color
map's range updated from the visible data). Writes GUI_TEST_MARKER: each
display's color map and the range of its Mean_Curvature_Clipped, the map's
range, and the visible scalar bars and their titles."""

import os

import numpy
from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMPVRepresentationProxy, vtkSMTransferFunctionManager

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]


def write_torus(path, scale, shift, count=20000, seed=7):
    """A torus (radii 1.5 and 1, times `scale`, moved by `shift` along x) with its outward normals."""
    generator = numpy.random.default_rng(seed)
    u, v = generator.uniform(0.0, 2.0 * numpy.pi, (2, count))
    ring = 1.5 + numpy.cos(v)
    points = scale * numpy.column_stack([ring * numpy.cos(u), ring * numpy.sin(u), numpy.sin(v)])
    points[:, 0] += shift
    normals = numpy.column_stack([numpy.cos(v) * numpy.cos(u), numpy.cos(v) * numpy.sin(u), numpy.sin(v)])
    numpy.savetxt(path, numpy.hstack([points, normals]), fmt="%.9g")


try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    view = simple.GetActiveViewOrCreate("RenderView")
    lines = []
    displays = []
    for name, scale, shift in (("one", 1.0, 0.0), ("two", 2.0, 8.0)):
        path = os.path.join(work, "torus_%s.xyz" % name)
        write_torus(path, scale, shift)
        cloud = simple.OpenDataFile(path)
        cloud.UpdatePipeline()
        curvatures = simple.PrincipalCurvatures(Input=cloud)
        simple.SetActiveSource(curvatures)
        display = simple.Show(curvatures, view)
        vtkSMPVRepresentationProxy.SetScalarBarVisibility(display.SMProxy, view.SMProxy, True)
        vtkSMTransferFunctionManager().ResetAllTransferFunctionRangesUsingCurrentData(
            servermanager.ProxyManager().SMProxyManager, True)
        clipped = servermanager.Fetch(curvatures).GetPointData().GetArray("Mean_Curvature_Clipped").GetRange()
        displays.append((name, display, clipped))
    simple.ResetCamera(view)
    simple.Render(view)
    for name, display, clipped in displays:
        points = display.LookupTable.RGBPoints
        lines.append("cloud %s map %s range %.9g %.9g data %.9g %.9g" % (
            name, display.LookupTable.SMProxy.GetGlobalIDAsString(), points[0], points[-4], clipped[0], clipped[1]))
    bars = [r for r in view.Representations
            if r.GetXMLName() == "ScalarBarWidgetRepresentation" and r.Visibility]
    lines.append("visible bars %d titled %s" % (len(bars), ",".join(sorted(b.Title for b in bars)) or "-"))
    with open(marker, "w") as handle:
        handle.write("ok\n" + "\n".join(lines) + "\n")
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
