"""Render a point cloud with its curvature lines (ridges and valleys) over
its points, colored by kind as in the GUI. Needs an X display (xvfb-run
works):

    xvfb-run -a pvpython Tools/render_curvature_lines.py INPUT OUTPUT.png
        [--color Mean_Curvature | --color none] [--line-kinds ridges-and-valleys|ridges|valleys|all]
        [--line-width 3] [--point-size 3] [--view x,y,z] [--up x,y,z] [--size W,H]

The curvatures and the lines are the filters' defaults. The points are
colored by --color (a point array of the curvatures' output, on a
blue-white-red map symmetric about zero and clipped at its 5th and 95th
percentiles) or gray with --color none; ridges are orange, valleys green
(the GUI's Line_Kind colors).

INPUT: any cloud Tools/estimate_curvatures.py reads (.vtp .vtu .ply .off
.xyz .pwn .txt .csv .las).
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import estimate_curvatures  # noqa: E402  (reading clouds, loading the plugin)
from curvature_lines_output import KIND_NAMES, LINE_KINDS, lines_filter, summarize_lines  # noqa: E402

from paraview import servermanager, simple  # noqa: E402
from render_view import color_symmetric, diagonal_of, make_view, save_picture  # noqa: E402

# Line_Kind's colors, as Plugin/Gui/pqCloudColorMapBehavior.cxx gives them.
KIND_COLORS = ((1.00, 0.60, 0.00), (0.00, 0.70, 0.35), (0.90, 0.35, 0.75),
               (0.55, 0.35, 0.10), (0.55, 0.85, 0.95), (0.35, 0.20, 0.60))


def parse_arguments(argv):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("input")
    parser.add_argument("output", help="picture (.png)")
    parser.add_argument("--color", default="Mean_Curvature", help="point array to color by, or none (gray)")
    parser.add_argument("--line-kinds", choices=sorted(LINE_KINDS), default="ridges-and-valleys")
    parser.add_argument("--line-width", type=float, default=3.0)
    parser.add_argument("--point-size", type=float, default=3.0)
    parser.add_argument("--view", default="0,0,1", help="camera direction towards the object, x,y,z")
    parser.add_argument("--up", default="0,1,0", help="camera up vector, x,y,z")
    parser.add_argument("--size", default="1600,1200")
    parser.add_argument("--plugin", default=estimate_curvatures.DEFAULT_PLUGIN)
    arguments = parser.parse_args(argv)
    if not os.path.isdir(os.path.dirname(os.path.abspath(arguments.output))):
        parser.error("the picture's folder does not exist: %s" % os.path.dirname(arguments.output))
    return arguments


def show_points(curvatures, view, arguments):
    """The cloud's points, by --color on a symmetric clipped map, or gray."""
    cloud = simple.Show(curvatures, view)
    cloud.Representation = "Points"
    cloud.PointSize = arguments.point_size
    if arguments.color.lower() == "none":
        cloud.ColorArrayName = ["POINTS", ""]
        cloud.AmbientColor = cloud.DiffuseColor = [0.72, 0.72, 0.72]
        return
    color_symmetric(cloud, curvatures, view, arguments.color)


def show_lines(lines, view, arguments, lift):
    """The lines by Line_Kind, with a legend of the kinds drawn; moved by
    `lift` towards the camera, so that the points they lie among do not
    hide parts of them."""
    lifted = simple.Transform(Input=lines)
    lifted.Transform.Translate = lift
    shown = simple.Show(lifted, view)
    shown.LineWidth = arguments.line_width
    simple.ColorBy(shown, ("CELLS", "Line_Kind"))
    lookup = simple.GetColorTransferFunction("Line_Kind")
    lookup.InterpretValuesAsCategories = 1
    codes = {"ridges": [0], "valleys": [1], "all": range(len(KIND_COLORS))}.get(arguments.line_kinds, [0, 1])
    lookup.Annotations = [v for code in codes for v in (str(code), KIND_NAMES[code].capitalize())]
    lookup.IndexedColors = [c for code in codes for c in KIND_COLORS[code]]
    shown.SetScalarBarVisibility(view, True)
    bar = simple.GetScalarBar(lookup, view)
    bar.Title = "Curvature lines"
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Upper Right Corner"


def main(argv):
    arguments = parse_arguments(argv)
    estimate_curvatures.load_plugin(arguments.plugin)
    source = estimate_curvatures.open_cloud(arguments.input)
    source.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=source)
    normals = estimate_curvatures.choose_normals(source, None)
    if normals:  # else the filter estimates them (NormalsSource Automatic)
        curvatures.Normals = ["POINTS", normals]
    curvatures.UpdatePipeline()
    lines = lines_filter(curvatures, arguments.line_kinds)
    lines.UpdatePipeline()
    summarize_lines(servermanager.Fetch(lines))

    view = make_view(arguments.size)
    show_points(curvatures, view, arguments)
    bounds = curvatures.GetDataInformation().DataInformation.GetBounds()
    direction = [float(v) for v in arguments.view.split(",")]
    norm = sum(v * v for v in direction) ** 0.5
    show_lines(lines, view, arguments, [-0.004 * diagonal_of(bounds) * v / norm for v in direction])
    save_picture(view, bounds, arguments.view, arguments.up, arguments.output)


if __name__ == "__main__":
    main(sys.argv[1:])
