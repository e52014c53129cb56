"""Render a point cloud colored by curvature, with short line glyphs along
the maximum principal direction. Needs an X display (xvfb-run works):

    xvfb-run -a pvpython Tools/render_principal_directions.py INPUT OUTPUT.png
        [--fit-mode OrientedCircles|Previous|New01|New02] [--color Mean_Curvature]
        [--glyph-every 8] [--view x,y,z]

The fit is the filter's default, OrientedCircles with the automatic
neighborhood, unless --fit-mode names one of the paper's (which then use a
radius holding about 375 neighbors).

INPUT: any cloud Tools/estimate_curvatures.py reads (.vtp .vtu .ply .off
.xyz .pwn .txt .csv).
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import estimate_curvatures  # noqa: E402  (reading clouds, loading the plugin)

from paraview import simple  # noqa: E402
from render_view import color_symmetric, diagonal_of, make_view, save_picture  # noqa: E402


def parse_arguments(argv):
    """The command line (also read by Testing/Python/TestSettingsAgree.py)."""
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("input")
    parser.add_argument("output", help="picture (.png)")
    parser.add_argument("--fit-mode", choices=estimate_curvatures.FIT_MODES, default="OrientedCircles",
                        help="the fit (default: %(default)s, the filter's default)")
    parser.add_argument("--color", default="Mean_Curvature", help="array to color by")
    parser.add_argument("--glyph-every", type=int, default=6, help="a glyph on every n-th point")
    parser.add_argument("--view", default="0,0,1", help="camera direction towards the object, x,y,z")
    parser.add_argument("--up", default="0,1,0", help="camera up vector, x,y,z")
    parser.add_argument("--size", default="1600,1200")
    parser.add_argument("--plugin", default=estimate_curvatures.DEFAULT_PLUGIN)
    return parser.parse_args(argv)


def main(argv):
    arguments = parse_arguments(argv)

    estimate_curvatures.load_plugin(arguments.plugin)
    source = estimate_curvatures.open_cloud(arguments.input)
    source.UpdatePipeline()
    curvatures = simple.PrincipalCurvatures(Input=source, FitMode=arguments.fit_mode)
    normals = estimate_curvatures.choose_normals(source, None)
    if normals:  # else the filter estimates them (NormalsSource Automatic)
        curvatures.Normals = ["POINTS", normals]
    curvatures.UpdatePipeline()
    bounds = curvatures.GetDataInformation().DataInformation.GetBounds()
    diagonal = diagonal_of(bounds)

    view = make_view(arguments.size)

    cloud = simple.Show(curvatures, view)
    cloud.Representation = "Points"
    cloud.PointSize = 4
    color_symmetric(cloud, curvatures, view, arguments.color)

    # Short line glyphs along the maximum principal direction (defined up to
    # sign: a line, not an arrow).
    masked = simple.MaskPoints(Input=curvatures, OnRatio=arguments.glyph_every, GenerateVertices=0,
                               MaximumNumberofPoints=10 ** 9)
    glyphs = simple.Glyph(Input=masked, GlyphType="Line")
    glyphs.OrientationArray = ["POINTS", "Maximum_Curvature_Direction"]
    glyphs.ScaleArray = ["POINTS", "No scale array"]
    glyphs.ScaleFactor = 0.012 * diagonal
    glyphs.GlyphMode = "All Points"
    lines = simple.Show(glyphs, view)
    lines.ColorArrayName = ["POINTS", ""]
    lines.AmbientColor = lines.DiffuseColor = [0.1, 0.1, 0.1]
    lines.LineWidth = 1.5

    save_picture(view, bounds, arguments.view, arguments.up, arguments.output)


if __name__ == "__main__":
    main(sys.argv[1:])
