"""What the render scripts (render_*.py) share: a white render view of a
given size; a cloud colored by an array on a blue-white-red map symmetric
about zero, with its legend; and a camera looking along a direction at the
data's center from three diagonals away, framing it, for the picture."""

import numpy
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy


def make_view(size):
    """A render view of SIZE ("width,height") on white, no axes."""
    view = simple.CreateView("RenderView")
    view.ViewSize = [int(v) for v in size.split(",")]
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:  # a ParaView before the color palette setting
        pass
    return view


def diagonal_of(bounds):
    return sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5


def place_camera(view, bounds, direction, up):
    """Looks along DIRECTION ("x,y,z", towards the object) with UP
    ("x,y,z") at the center of BOUNDS, framing them."""
    diagonal = diagonal_of(bounds)
    toward = [float(v) for v in direction.split(",")]
    center = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
    view.CameraFocalPoint = center
    view.CameraPosition = [center[k] - toward[k] * 3 * diagonal for k in range(3)]
    view.CameraViewUp = [float(v) for v in up.split(",")]
    simple.ResetCamera(view)
    simple.GetActiveCamera().Dolly(1.3)


def save_picture(view, bounds, direction, up, output):
    """Places the camera (place_camera), renders, and writes the view's
    picture to OUTPUT."""
    place_camera(view, bounds, direction, up)
    simple.Render(view)
    simple.SaveScreenshot(output, view, ImageResolution=view.ViewSize)
    print("wrote %s" % output)


def color_symmetric(display, source, view, array):
    """Colors DISPLAY (of SOURCE) by the point ARRAY on "Cool to Warm" from
    -b to b, b the larger |5th or 95th percentile| (curvature has long
    tails at sharp features), with a legend titled by the array's name."""
    simple.ColorBy(display, ("POINTS", array))
    lookup = simple.GetColorTransferFunction(array)
    lookup.ApplyPreset("Cool to Warm", True)
    values = vtk_to_numpy(servermanager.Fetch(source).GetPointData().GetArray(array))
    bound = max(numpy.abs(numpy.nanpercentile(values, [5, 95]))) if values.size else 1.0
    lookup.RescaleTransferFunction(-bound, bound)
    display.SetScalarBarVisibility(view, True)
    bar = simple.GetScalarBar(lookup, view)
    bar.Title = array.replace("_", " ")
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
