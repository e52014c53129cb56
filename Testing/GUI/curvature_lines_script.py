"""Runs inside the ParaView GUI (paraview --script=...) for
RunCurvatureLinesTest.sh: loads the plugin, opens an extruded Gaussian bump
(a ridge along x = 0, a valley on each side) with exact normals, leaves it
for the driver to apply, and writes a marker file when the GUI is ready for
keys. From then on, after every render of the view, it rewrites
GUI_TEST_WORK/state: the sources shown, whether the curvatures are shown,
and for the lines' display its coloring (array and association), line
width, whether its map is categorical, its annotations, and whether its
legend shows. The driver
applies the cloud, creates Principal Curvatures and Curvature Lines by the
quick launch, and applies each. Then, asked by GUI_TEST_WORK/request, it
shows Curvature Lines of a flat plane (no line) as a new display, and
writes GUI_TEST_WORK/empty: its cells, coloring and whether a legend
shows."""

import os

import numpy
from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMPVRepresentationProxy

marker = os.environ["GUI_TEST_MARKER"]
work = os.environ["GUI_TEST_WORK"]


def write_bump(path, seed=5):
    """z = 0.5 exp(-x^2 / 2) over [-4, 4]^2, jittered grid, exact normals."""
    rng = numpy.random.default_rng(seed)
    grid = (numpy.arange(173) + 0.5) * 8.0 / 173 - 4.0
    x, y = (v.ravel() + rng.uniform(-0.01, 0.01, v.size) for v in numpy.meshgrid(grid, grid))
    z = 0.5 * numpy.exp(-0.5 * x * x)
    normals = numpy.column_stack([x * z, numpy.zeros_like(x), numpy.ones_like(x)])
    normals /= numpy.linalg.norm(normals, axis=1)[:, None]
    numpy.savetxt(path, numpy.column_stack([x, y, z, normals]), fmt="%.9g")


def write_plane(path):
    """A flat grid with its normals: no curvature, no line."""
    grid = numpy.arange(60) * 0.1
    x, y = (v.ravel() for v in numpy.meshgrid(grid, grid))
    flat = numpy.column_stack([x, y, numpy.zeros_like(x), numpy.zeros_like(x), numpy.zeros_like(x),
                               numpy.ones_like(x)])
    numpy.savetxt(path, flat, fmt="%.9g")


def show_empty_lines(caller, event):
    """Asked once: Curvature Lines of a plane, shown; what the display is."""
    request = os.path.join(work, "request")
    if not os.path.exists(request):
        return
    os.remove(request)
    try:
        view = simple.GetActiveView()
        path = os.path.join(work, "plane.xyz")
        write_plane(path)
        lines = simple.CurvatureLines(Input=simple.PrincipalCurvatures(Input=simple.OpenDataFile(path)))
        display = simple.Show(lines, view)
        simple.Render(view)
        text = "empty lines %d colored_by %s legend %d\n" % (
            lines.GetDataInformation().GetNumberOfCells(), display.ColorArrayName[1] or "-",
            vtkSMPVRepresentationProxy.IsScalarBarVisible(display.SMProxy, view.SMProxy))
    except Exception as error:  # the driver reports it
        text = "error %s\n" % error
    with open(os.path.join(work, "empty"), "w") as handle:
        handle.write(text)


def shown(source, view):
    # servermanager's lookup: simple's would make a display.
    display = servermanager.GetRepresentation(source, view)
    return display if display is not None and display.Visibility else None


def record_state(caller, event):
    try:
        view = simple.GetActiveView()
        lines = []
        for source in simple.GetSources().values():
            display = shown(source, view)
            if display is None:
                continue
            lines.append("shown %s\n" % source.GetXMLName())
            if source.GetXMLName() == "PrincipalCurvatureEstimation":
                lines.append("curvatures shown\n")
            if source.GetXMLName() != "CurvatureLines":
                continue
            color_map = display.LookupTable
            lines += ["lines shown %d\n" % source.GetDataInformation().GetNumberOfCells(),
                      "colored by %s %s\n" % (display.ColorArrayName[0], display.ColorArrayName[1]),
                      "line width %g\n" % display.LineWidth,
                      "categorical %d\n" % (color_map.InterpretValuesAsCategories if color_map else -1),
                      "annotations %s\n" % (",".join(color_map.Annotations) if color_map else "-"),
                      "legend %d\n" % vtkSMPVRepresentationProxy.IsScalarBarVisible(display.SMProxy, view.SMProxy)]
        with open(os.path.join(work, "state"), "w") as handle:
            handle.writelines(sorted(lines))
    except Exception as error:  # the driver reports it
        with open(os.path.join(work, "state"), "w") as handle:
            handle.write("error %s\n" % error)


try:
    simple.LoadPlugin(os.environ["GUI_TEST_PLUGIN"], remote=False)
    path = os.path.join(work, "bump.xyz")
    write_bump(path)
    cloud = simple.OpenDataFile(path)
    simple.SetActiveSource(cloud)
    view = simple.GetActiveViewOrCreate("RenderView")
    view.OrientationAxesVisibility = 0
    view.GetRenderWindow().AddObserver("EndEvent", record_state)
    interactor = view.GetRenderWindow().GetInteractor()
    interactor.AddObserver("TimerEvent", show_empty_lines)
    interactor.CreateRepeatingTimer(200)
    with open(marker, "w") as handle:
        handle.write("ready\n")
except Exception as error:  # report to the driver instead of a silent GUI
    with open(marker, "w") as handle:
        handle.write("error %s\n" % error)
