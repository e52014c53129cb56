"""Estimate the principal curvatures of a point cloud, with or without normals.

Run with ParaView's Python:

    pvpython Tools/estimate_curvatures.py INPUT OUTPUT(.vtp|.ply|.csv|.las)
        [--fit-mode OrientedCircles|Previous|New01|New02] [--neighbors N] [--k-nearest]
        [--radius S [--plane-distance P]]
        [--dynamic-adjustment [paper|ladder|noisy-ladder]]
        [--normals NAME | --estimate-normals] [--orientation outward|viewpoint|axis]
        [--viewpoint X Y Z] [--axis X Y Z] [--threads T] [--plugin PATH]
        [--single-precision] [--no-diagnostics] [--progress | --no-progress]
        [--lines [PATH]] [--line-kinds ridges-and-valleys|ridges|valleys|all]

Without normals in the input (an x y z scan), the normals are estimated and
oriented (outward by default) and written to OUTPUT as Normals; colors are
never taken for normals.

INPUT may be:

  .vtp .vtu       VTK XML point sets with a 3-component point-data normals
                  array (or scalar arrays nx ny nz, combined into one);
  .ply            PLY (ascii or binary), its vertices: x y z (double kept
                  double), normals as nx ny nz (or normal_x normal_y
                  normal_z), every other vertex property as an array; read
                  by the plugin's PLY Point Cloud Reader;
  .las            LAS 1.0-1.4 lidar points (formats 0-10, uncompressed;
                  decompress .laz first), double coordinates and PDAL's
                  array names; read by the plugin's LAS Point Cloud Reader;
  .xyz .pwn .txt .pts .csv
                  text, one point per line: x y z nx ny nz [more columns],
                  separated by white space, commas or semicolons; '#' or '//'
                  starts a comment; a first line holding only the point
                  count (PTS) is skipped; an optional first line of column
                  names (x, y, z, nx, ny, nz or normal_x, ...) picks the
                  columns. Read by the plugin's Point Cloud Text Reader
                  (vtkTextPointCloudReader: its class documentation has the
                  rules for colors and further columns);
  .off            a triangle mesh, read by the plugin's OFF Mesh Reader
                  (vtkOFFMeshReader): its vertices, with normals computed
                  from the triangles and turned outwards;
  .obj            Wavefront OBJ (ParaView's reader): its vertices, with
                  their normals (vn) if it has them, else normals from its
                  faces as for .off, else (vertices only) estimated ones.

Writes OUTPUT with the input's arrays and the curvature arrays, in the
format of its extension: .vtp (VTK XML, inline binary); .ply (binary little
endian: x y z, nx ny nz, red green blue for an RGB array, every scalar array
as a property of its name and type and every vector array as <name>_x
<name>_y <name>_z, which CloudCompare and MeshLab read as scalar fields,
and the plugin's PLY reader back as the arrays); .csv (a header line of
the same column names, one row per point, every value exact). Both are
written by the plugin's PLY and CSV Point Cloud Writers. .las (LAS 1.4
through the plugin's LAS Point Cloud Writer: the lidar fields as such,
every other array as described extra bytes, and a LAS input's scale,
offset and coordinate system kept).
It prints a summary: point counts (the unestimated ones by reason), the
thresholds used, percentiles of the curvatures over the estimated points,
and the time the filter took. On a terminal it also shows the stages and a
progress line on stderr (--progress shows them when piped too,
--no-progress never). --single-precision writes the arrays as float,
--no-diagnostics leaves out the arrays that say how each point was
estimated; with either, a .vtp is also compressed (zlib), and with
--single-precision a .ply or .csv has float points where float keeps them
to a millionth of the cloud's size. Together they make a 3M-point result
less than 40 % of the default size.

--lines also writes the curvature lines (docs/curvature-lines.md: ridges
and valleys by default, every extremal line with --line-kinds all) to PATH,
by default OUTPUT's stem + _lines.vtp: .vtp (polylines with cell data
Line_Kind, Line_Strength, Line_Length and point data Line_Curvature, for
ParaView) or .ply (binary: a vertex element x y z Line_Curvature and an
edge element vertex1 vertex2 Line_Kind Line_Strength Line_Length, one edge
per segment, for MeshLab and CloudCompare, and which the plugin's PLY
reader reads back as lines). Give PATH as --lines=PATH or after INPUT and OUTPUT. The
summary then also counts the lines by kind, with their length.

The plugin is loaded from --plugin, else $PRINCIPAL_CURVATURES_PLUGIN, else
the build tree next to this script; not at all if it is already loaded
(PV_PLUGIN_CONFIG_FILE pointing at the build's plugins XML autoloads it).
Exit code 0 on success, 2 with a message on bad input.
"""

import argparse
import os
import sys
import time

from paraview import servermanager, simple

# Its sibling module, also when this file is loaded by path (tests do).
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from curvature_lines_output import (LINE_KINDS, default_lines_path, lines_filter,  # noqa: E402
                                    lines_path_problem, summarize_lines, write_lines)

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_PLUGIN = os.path.join(
    REPOSITORY, "build", "lib", "paraview-plugins", "PrincipalCurvatures", "PrincipalCurvatures.so")
TEXT_EXTENSIONS = (".xyz", ".pwn", ".txt", ".pts", ".csv")
LAS_EXTENSIONS = (".las", ".laz")
INPUT_EXTENSIONS = (".vtp", ".vtu", ".ply") + LAS_EXTENSIONS + (".off", ".obj") + TEXT_EXTENSIONS
OUTPUT_EXTENSIONS = (".vtp", ".ply", ".csv", ".las")
FIT_MODES = ("Previous", "New01", "New02", "OrientedCircles")

# Names of normal components stored as separate scalars (matched ignoring case).
NORMAL_COMPONENT_NAMES = (("nx", "ny", "nz"), ("normal_x", "normal_y", "normal_z"),
                          ("normalx", "normaly", "normalz"), ("n_x", "n_y", "n_z"))
CURVATURE_ARRAYS = ("Minimum_Curvature", "Maximum_Curvature", "Mean_Curvature", "Gauss_Curvature")


def fail(message):
    """Prints message to stderr and exits with status 2."""
    sys.stderr.write("estimate_curvatures: error: %s\n" % message)
    sys.exit(2)


# ---------------------------------------------------------------------------
# VTK's messages


def vtk_message_text(text):
    """A VTK error or warning as one plain line: without the "ERROR: In
    file, line N" preamble and the object's address."""
    import re

    text = re.sub(r"^(ERROR|Warning|Generic Warning): In [^\n]*\n", "", text.strip())
    return re.sub(r"^(\w+) \(0x[0-9a-fA-F]+\): ", r"\1: ", text).strip()


def plain_vtk_messages():
    """Shows VTK's errors and warnings as plain "estimate_curvatures: error:
    ..." lines on stderr: VTK's own log lines carry a time and thread
    prefix and terminal color codes, even into a pipe or a file. Fatal
    messages (a crash's stack trace) still go through VTK's log."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.vtkCommonCore import VTK_STRING, vtkLogger, vtkOutputWindow

    fatal = vtkLogger.ConvertToVerbosity(-3)  # loguru's FATAL, not wrapped by name
    vtkLogger.SetStderrVerbosity(fatal)
    window = vtkOutputWindow.GetInstance()
    window.SetDisplayModeToNever()  # the events below still fire

    def show(kind):
        @calldata_type(VTK_STRING)
        def observer(caller, event, text):
            # Straight to the stream: printing through Python's sys.stderr
            # from here can re-enter VTK's output window. A progress line
            # being drawn is ended first, so the message starts a line.
            start = "\n" if Progress.line_open else ""
            Progress.line_open = False
            sys.__stderr__.write("%sestimate_curvatures: %s: %s\n" % (start, kind, vtk_message_text(text)))
            sys.__stderr__.flush()
        return observer

    window.AddObserver("ErrorEvent", show("error"))
    window.AddObserver("WarningEvent", show("warning"))


# ---------------------------------------------------------------------------
# Command line


# The --orientation names and the filter's.
ORIENTATIONS = {"outward": "Outward", "viewpoint": "Towards Viewpoint", "axis": "Along Axis"}


def parse_arguments(argv):
    """The command line, checked for contradictions."""
    parser = argparse.ArgumentParser(
        prog="pvpython estimate_curvatures.py", description=__doc__.split("\n\n")[0],
        epilog="\n\n".join(__doc__.split("\n\n")[3:]), formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("input", help="point cloud with normals (%s)" % " ".join(INPUT_EXTENSIONS))
    parser.add_argument("output", help="result (%s, by the extension)" % " ".join(OUTPUT_EXTENSIONS))
    parser.add_argument("--fit-mode", choices=FIT_MODES,
                        help="the fit (default: OrientedCircles with the automatic neighborhood; New01, the "
                             "paper's, with --dynamic-adjustment)")
    parser.add_argument("--neighbors", type=int, metavar="N",
                        help="a fixed neighborhood: the radius holding about N neighbors, or k with --k-nearest "
                             "(default: chosen per point from the data)")
    parser.add_argument("--k-nearest", action="store_true", help="use the N nearest neighbors instead of a radius")
    parser.add_argument("--radius", type=float, metavar="S",
                        help="fixed surroundings-threshold s (turns the automatic thresholds off)")
    parser.add_argument("--plane-distance", type=float, metavar="P",
                        help="fixed plane-distance-threshold p, with --radius (default: S / 10)")
    parser.add_argument("--dynamic-adjustment", nargs="?", const="paper", choices=sorted(ADJUSTMENTS),
                        help="the paper's dynamic variable adjustment (replaces the neighborhood options): "
                             "with the paper's constants (the default), or the banded ladder of docs/dynamic-adjustment.md "
                             "for noise-free or noisy clouds")
    parser.add_argument("--normals", metavar="NAME",
                        help="point-data normals array to use; an error if it is not normals (default: the "
                             "normals attribute, or an array named like normals, or else estimated normals)")
    parser.add_argument("--estimate-normals", action="store_true",
                        help="estimate the normals even if the input has some")
    # Settings without a value given keep the filter's defaults
    # (Core/Settings/SettingsTable.h, docs/settings.md).
    parser.add_argument("--orientation", choices=sorted(ORIENTATIONS),
                        help="how estimated normals are signed: outward (up where a part's inside cannot be "
                             "told), towards --viewpoint, or along --axis (default: the filter's NormalOrientation)")
    parser.add_argument("--viewpoint", type=float, nargs=3, metavar=("X", "Y", "Z"),
                        help="where the scanner was, with --orientation viewpoint (default: the filter's Viewpoint)")
    parser.add_argument("--axis", type=float, nargs=3, metavar=("X", "Y", "Z"),
                        help="the direction estimated normals point along, with --orientation axis (default: the "
                             "filter's OrientationAxis)")
    parser.add_argument("--threads", type=int, metavar="T",
                        help="at most T threads, 0 for all cores (default: the filter's NumberOfThreads)")
    parser.add_argument("--single-precision", action="store_true",
                        help="write the output arrays as float, not double; in a .ply or .csv the points too, "
                             "where float keeps them to a millionth of the cloud's size")
    parser.add_argument("--no-diagnostics", action="store_true",
                        help="leave out Neighbor_Count, Valid_Direction_Count, Sine_Fit_RMS, Surroundings_Threshold, "
                             "Plane_Distance_Threshold, Curvature_Standard_Error and Target_Neighbor_Count")
    shown = parser.add_mutually_exclusive_group()
    shown.add_argument("--progress", dest="progress", action="store_true", default=None,
                       help="show the stages and a progress line on stderr (default: when stderr is a terminal)")
    shown.add_argument("--no-progress", dest="progress", action="store_false",
                       help="never show them")
    parser.add_argument("--lines", nargs="?", const="", metavar="PATH",
                        help="also write the curvature lines (ridges and valleys) to PATH, .vtp or .ply (PLY "
                             "vertices and edges); without PATH, OUTPUT's stem + _lines.vtp. Give PATH as "
                             "--lines=PATH or after INPUT OUTPUT")
    parser.add_argument("--line-kinds", choices=sorted(LINE_KINDS), default="ridges-and-valleys",
                        help="which lines --lines writes (default: %(default)s; all: every extremal line)")
    parser.add_argument("--plugin", metavar="PATH",
                        default=os.environ.get("PRINCIPAL_CURVATURES_PLUGIN") or DEFAULT_PLUGIN,
                        help="PrincipalCurvatures.so (default: $PRINCIPAL_CURVATURES_PLUGIN or %(default)s)")
    arguments = parser.parse_args(argv)

    if arguments.neighbors is not None and arguments.neighbors < 3:
        parser.error("--neighbors must be at least 3")
    if arguments.radius is not None and not arguments.radius > 0:
        parser.error("--radius must be positive")
    if arguments.plane_distance is not None:
        if arguments.radius is None:
            parser.error("--plane-distance needs --radius (automatic thresholds derive it from the radius)")
        if not arguments.plane_distance > 0:
            parser.error("--plane-distance must be positive")
    if arguments.fit_mode is None:
        arguments.fit_mode = "New01" if arguments.dynamic_adjustment else "OrientedCircles"
    if arguments.dynamic_adjustment and (arguments.radius or arguments.k_nearest or arguments.neighbors):
        parser.error("--dynamic-adjustment replaces --neighbors, --k-nearest and --radius")
    if arguments.threads is not None and arguments.threads < 0:
        parser.error("--threads must be 0 (all cores) or positive")
    if arguments.progress is None:
        arguments.progress = sys.stderr.isatty()
    if os.path.splitext(arguments.output)[1].lower() not in OUTPUT_EXTENSIONS:
        parser.error("OUTPUT must be a %s file (got %s)" % ("/".join(OUTPUT_EXTENSIONS), arguments.output))
    if arguments.lines == "":
        arguments.lines = default_lines_path(arguments.output)
    problem = arguments.lines is not None and lines_path_problem(arguments.lines, arguments.output)
    if problem:
        parser.error(problem)
    return arguments


# ---------------------------------------------------------------------------
# The plugin


def load_plugin(path):
    """Makes simple.PrincipalCurvatures available: loads the plugin at path
    unless it is already loaded (autoloaded through PV_PLUGIN_CONFIG_FILE)."""
    if hasattr(simple, "PrincipalCurvatures"):
        return
    if not os.path.isfile(path):
        fail("plugin not found: %s (build it with Scripts/setup.sh, or pass --plugin or set "
             "PRINCIPAL_CURVATURES_PLUGIN)" % path)
    try:
        # Without ns, LoadPlugin adds the new functions to paraview.simple.
        simple.LoadPlugin(path, remote=False)
    except RuntimeError as error:
        fail("cannot load the plugin: %s" % error)
    if not hasattr(simple, "PrincipalCurvatures"):
        fail("loading %s did not provide the PrincipalCurvatures filter" % path)


# ---------------------------------------------------------------------------
# Reading clouds


def producer_of(cloud):
    """A pipeline source (TrivialProducer) holding an in-memory data set."""
    producer = simple.TrivialProducer()
    producer.GetClientSideObject().SetOutput(cloud)
    return producer


def normal_columns(names):
    """Indices of the x y z and normal components among column or property
    names (ignoring case), or None where missing."""
    lower = [name.lower() for name in names]
    position = [lower.index(c) if c in lower else None for c in ("x", "y", "z")]
    for triple in NORMAL_COMPONENT_NAMES:
        if all(c in lower for c in triple):
            return position, [lower.index(c) for c in triple]
    return position, None


class ReaderErrors:
    """The error messages of a reader's VTK object, kept to be reported as
    the tool's own (the reader then prints none itself)."""

    def __init__(self, proxy):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.vtkCommonCore import VTK_STRING

        self.messages = []

        @calldata_type(VTK_STRING)
        def keep(caller, event, text):
            self.messages.append(vtk_message_text(text).split(": ", 1)[-1])

        proxy.GetClientSideObject().AddObserver("ErrorEvent", keep)


def updated_reader(source):
    """The plugin's reader source, updated; exits with its messages (file,
    line, what is wrong) if it failed."""
    errors = ReaderErrors(source)
    source.UpdatePipeline()
    if errors.messages:
        fail("; ".join(errors.messages))
    return source


def read_text_cloud(path):
    """A source reading a text cloud (x y z nx ny nz ... per line) with the
    plugin's Point Cloud Text Reader (vtkTextPointCloudReader), as the GUI
    does, so that both read the same files alike: a bad line is an error
    naming it, NaN coordinates are kept (and left unestimated), with one
    warning. Exits with the reader's message if it fails."""
    return updated_reader(simple.PointCloudTextReader(FileName=path))


READER_ERRORS = {}  # the plugin readers' error messages, by file


def read_point_cloud_file(path, extension):
    """A source reading a .ply (its vertices) or .las with the plugin's PLY
    or LAS Point Cloud Reader. The PLY reader keeps double coordinates and
    every vertex property, takes normals named nx ny nz or normal_x ..., and
    reports a header without a vertex element or without x, y, z (where
    VTK's own PLY reader crashes); the LAS reader reports LAZ compression
    and headers that do not match the file. Either gives no points after an
    error, whose messages are kept in READER_ERRORS[path]."""
    if extension == ".ply":
        source = simple.PLYPointCloudReader(FileName=path)
    else:
        source = simple.LASPointCloudReader(FileName=path)
    errors = READER_ERRORS.setdefault(path, [])

    from vtkmodules.util.misc import calldata_type
    from vtkmodules.vtkCommonCore import VTK_STRING

    @calldata_type(VTK_STRING)
    def keep(caller, event, message):
        # "ERROR: In file, line N\nclass (address): the message": the message.
        errors.append(message.strip().splitlines()[-1].split("): ", 1)[-1])

    source.GetClientSideObject().AddObserver("ErrorEvent", keep)
    return source


def read_off_mesh(path):
    """An OFF triangle mesh with the plugin's OFF Mesh Reader
    (vtkOFFMeshReader), as the GUI reads it: its vertices, with point normals
    from the triangles turned to point away from the centroid (for a closed,
    roughly star-shaped scan such as the Stanford bunny); without faces,
    none (they are estimated). Exits with the reader's message if it fails."""
    return updated_reader(simple.OFFMeshReader(FileName=path))


def with_outward_normals(mesh):
    """The polydata mesh with point normals computed from its polygons,
    made consistent, and turned to point away from the centroid: the OFF
    Mesh Reader's rule (FileFormats/MeshOrientation.h), for the OBJ meshes
    it does not read; TestCommandLineMeshes checks that both agree."""
    import numpy
    from vtkmodules.numpy_interface import dataset_adapter
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals

    normals = vtkPolyDataNormals()
    normals.SetInputData(mesh)
    normals.ComputePointNormalsOn()
    normals.ComputeCellNormalsOff()
    normals.SplittingOff()
    normals.ConsistencyOn()
    normals.Update()
    cloud = dataset_adapter.WrapDataObject(normals.GetOutput())
    outward = ((cloud.Points - cloud.Points.mean(axis=0)) * cloud.PointData["Normals"]).sum(axis=1)
    if numpy.median(outward) < 0:
        cloud.PointData["Normals"][:] *= -1
    return cloud.VTKObject


def read_obj(path):
    """A Wavefront OBJ file with ParaView's reader: its vertices, with their
    normals (vn) where the file gives them; else, for a mesh, normals from
    its faces as for OFF; else (vertices only) none, for the filter to
    estimate."""
    source = simple.WavefrontOBJReader(FileName=path)
    source.UpdatePipeline()
    mesh = servermanager.Fetch(source)
    if mesh is None or mesh.GetNumberOfPoints() == 0:
        fail("%s: no vertices (not an OBJ file, or an empty one; see the messages above)" % path)
    if mesh.GetPointData().GetNormals() is None and mesh.GetNumberOfPolys() > 0:
        print("normals from the OBJ faces")
        return producer_of(with_outward_normals(mesh))
    return source


def point_arrays(source):
    """{name: number of components} of the source's point data."""
    arrays = source.PointData
    return {name: arrays[name].GetNumberOfComponents() for name in arrays.keys()}


def normals_attribute(source):
    """The name of the array flagged as the point normals, or None."""
    from vtkmodules.vtkCommonDataModel import vtkDataSetAttributes

    information = source.GetDataInformation().DataInformation.GetPointDataInformation()
    array = information.GetAttributeInformation(vtkDataSetAttributes.NORMALS)
    return array.GetName() if array is not None and array.GetNumberOfComponents() == 3 else None


def named_normals(source):
    """3-component point arrays whose name contains 'normal', 'Normals' first."""
    names = [name for name, components in point_arrays(source).items()
             if components == 3 and "normal" in name.lower()]
    return sorted(names, key=lambda name: name != "Normals")


def has_normals(source):
    """Whether the source has a 3-component normals array to choose by default."""
    return normals_attribute(source) is not None or bool(named_normals(source))


def combine_normal_components(source):
    """A Calculator adding a 3-component 'Normals' array made of scalar
    arrays nx ny nz (or normal_x ...), or None if the source has none."""
    scalars = [name for name, components in point_arrays(source).items() if components == 1]
    _, normal = normal_columns(scalars)
    if normal is None:
        return None
    x, y, z = (scalars[i] for i in normal)
    print("normals from the point arrays %s %s %s" % (x, y, z))
    combined = simple.Calculator(Input=source, AttributeType="Point Data", ResultArrayName="Normals",
                                 ResultNormals=1, Function="%s*iHat + %s*jHat + %s*kHat" % (x, y, z))
    combined.UpdatePipeline()
    return combined


def open_cloud(path):
    """A pipeline source for the cloud in path, updated, and with a
    3-component normals array where the file stores normals differently."""
    if not os.path.isfile(path):
        fail("input not found: %s" % path)
    extension = os.path.splitext(path)[1].lower()
    if extension == ".vtp":
        source = simple.XMLPolyDataReader(FileName=[path])
    elif extension == ".vtu":
        source = simple.XMLUnstructuredGridReader(FileName=[path])
    elif extension in (".ply",) + LAS_EXTENSIONS:
        source = read_point_cloud_file(path, extension)
    elif extension in TEXT_EXTENSIONS:
        source = read_text_cloud(path)
    elif extension == ".off":
        source = read_off_mesh(path)
    elif extension == ".obj":
        source = read_obj(path)
    else:
        fail("unknown input type '%s' of %s (use %s)" % (extension, path, " ".join(INPUT_EXTENSIONS)))
    source.UpdatePipeline()  # fills the array lists the filter's Normals domain reads
    if source.GetDataInformation().GetNumberOfPoints() == 0:
        errors = READER_ERRORS.get(path)
        fail(errors[-1] if errors else "%s: no points (unreadable or empty file; see the messages above)" % path)
    if not has_normals(source):
        source = combine_normal_components(source) or source
    return source


def choose_normals(source, requested):
    """The normals array to use: the requested one; else the array flagged
    as the normals attribute; else a 3-component array named like normals;
    else None (the filter estimates them). Exits with a message if the
    requested one is not there."""
    arrays = point_arrays(source)
    listing = ", ".join("%s (%d)" % item for item in sorted(arrays.items())) or "none"
    if requested:
        if requested not in arrays:
            fail("no point-data array named '%s' (have: %s); leave out --normals, or give "
                 "--estimate-normals, to estimate normals" % (requested, listing))
        if arrays[requested] != 3:
            fail("the array '%s' has %d components, normals need 3; leave out --normals, or give "
                 "--estimate-normals, to estimate normals" % (requested, arrays[requested]))
        return requested
    return normals_attribute(source) or next(iter(named_normals(source)), None)


def configure_normals(curvatures, arguments, normals):
    """Sets where the normals come from; returns how the summary names them."""
    if arguments.orientation is not None:
        curvatures.NormalOrientation = ORIENTATIONS[arguments.orientation]
    if arguments.viewpoint is not None:
        curvatures.Viewpoint = arguments.viewpoint
    if arguments.axis is not None:
        curvatures.OrientationAxis = arguments.axis
    if arguments.estimate_normals or normals is None:
        curvatures.NormalsSource = "Estimated"
        named = {text: name for name, text in ORIENTATIONS.items()}
        return "estimated (%s)" % named[curvatures.NormalOrientation.GetData()]
    curvatures.Normals = ["POINTS", normals]
    # A named array must be normals: an error, not a silent estimate.
    curvatures.NormalsSource = "Input Array" if arguments.normals else "Automatic"
    return normals


# ---------------------------------------------------------------------------
# Running and reporting


class Progress:
    """Stage lines and a progress line on stderr, or nothing."""

    line_open = False  # a stage's line is drawn and not yet ended

    def __init__(self, shown):
        self.shown = shown
        self.stage = None
        self.percent = None

    def begin(self, stage):
        self.end()
        self.stage, self.percent = stage, None
        if self.shown:
            sys.stderr.write(stage + " ...")
            sys.stderr.flush()
            Progress.line_open = True

    def watch(self, proxy):
        """Shows the progress of the proxy's filter while it runs (its
        progress events arrive on this thread)."""
        if self.shown:
            proxy.GetClientSideObject().AddObserver(
                "ProgressEvent", lambda algorithm, _: self.update(algorithm.GetProgress()))

    def update(self, fraction):
        percent = int(100 * fraction)
        if self.shown and percent != self.percent:
            self.percent = percent
            sys.stderr.write("\r%s ... %3d %%" % (self.stage, percent))
            Progress.line_open = True
            sys.stderr.flush()

    def end(self):
        if self.shown and self.stage:
            sys.stderr.write("\r%s ... done%s\n" % (self.stage, " " * 4))
            Progress.line_open = False
            sys.stderr.flush()
        self.stage = None

# The dynamic adjustment's constants by --dynamic-adjustment name: the
# paper's are the filter's defaults; the banded ladders as the filter's
# presets give them (docs/dynamic-adjustment.md; TestSettingsAgree.py checks
# them against vtkPrincipalCurvatureEstimation::SetAdjustmentConstantsToPreset).
ADJUSTMENTS = {
    "paper": {},
    "ladder": {"TargetNeighborCounts": [375, 750, 1500], "TargetPlaneDistances": [0.2, 0.2, 0.2],
               "SwitchLengths": [4.5, 3.2, 7.2]},
    "noisy-ladder": {"TargetNeighborCounts": [1000, 2000, 4000], "TargetPlaneDistances": [0.6, 0.6, 0.6],
                     "SwitchLengths": [4.5, 3.2, 7.2]},
}


def configure(curvatures, arguments):
    """Sets the filter's properties from the command line."""
    curvatures.FitMode = arguments.fit_mode
    if arguments.threads is not None:
        curvatures.NumberOfThreads = arguments.threads
    curvatures.SinglePrecisionOutput = int(arguments.single_precision)
    curvatures.DiagnosticArrays = int(not arguments.no_diagnostics)
    fixed = arguments.neighbors or arguments.k_nearest or arguments.radius
    curvatures.NeighborhoodMode = "Radius" if fixed else "Automatic"
    if arguments.dynamic_adjustment:
        curvatures.DynamicAdjustment = 1
        for name, value in ADJUSTMENTS[arguments.dynamic_adjustment].items():
            setattr(curvatures, name, value)
        return
    if arguments.neighbors:
        curvatures.NumberOfNeighbors = arguments.neighbors
    if arguments.k_nearest:
        curvatures.NeighborhoodMode = "K Nearest"
    if arguments.radius:
        curvatures.AutomaticThresholds = 0
        curvatures.SurroundingsThreshold = arguments.radius
        curvatures.PlaneDistanceThreshold = arguments.plane_distance or 0.1 * arguments.radius


def neighborhood_description(curvatures):
    """One line on the neighborhood settings in use."""
    if curvatures.DynamicAdjustment:
        return "dynamic adjustment: target counts %s, plane distances %s L, switch lengths %s L" % tuple(
            " ".join("%g" % v for v in getattr(curvatures, name))
            for name in ("TargetNeighborCounts", "TargetPlaneDistances", "SwitchLengths"))
    k, automatic = curvatures.NumberOfNeighbors, curvatures.AutomaticThresholds
    if curvatures.NeighborhoodMode == "Automatic" and curvatures.FitMode == "OrientedCircles":
        return "automatic: per point, the largest radius whose curvatures agree with the smaller ones'"
    if curvatures.NeighborhoodMode == "K Nearest":
        neighbors = "the %d nearest points" % k
        plane = "p = %g x median distance to the %d-th neighbor" % (curvatures.PlaneDistanceRatio, k) \
            if automatic else "p = %g" % curvatures.PlaneDistanceThreshold
    elif automatic:
        neighbors = "radius s = median distance to the %d-th neighbor" % k
        plane = "p = %g s" % curvatures.PlaneDistanceRatio
    else:
        neighbors = "radius s = %g" % curvatures.SurroundingsThreshold
        plane = "p = %g" % curvatures.PlaneDistanceThreshold
    return "%s, %s" % (neighbors, plane)


def percentiles_row(name, values):
    """name, then min, 5 %, median, 95 %, max of values."""
    import numpy

    if values.size == 0:
        return "%-26s %s" % (name, "no estimate")
    row = numpy.percentile(values, [0, 5, 50, 95, 100])
    return "%-26s" % name + "".join(" %12.5g" % v for v in row)


def summarize(output, seconds, description):
    """Prints the summary table of the filter's output."""
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    data = output.GetPointData()

    def array(name):
        return vtk_to_numpy(data.GetArray(name))

    n = output.GetNumberOfPoints()
    valid = array("Curvature_Valid").astype(bool)
    estimated = int(valid.sum())
    share = 100.0 / max(n, 1)
    for label, value in description:
        print("%-26s %s" % (label, value))
    print("%-26s %d" % ("points", n))
    print("%-26s %d (%.2f %%)" % ("estimated", estimated, estimated * share))
    print("%-26s %d (%.2f %%)" % ("not estimated", n - estimated, (n - estimated) * share))
    field = output.GetFieldData()
    for index in range(field.GetNumberOfArrays()):
        name = field.GetArrayName(index) or ""
        if not name.startswith("Unestimated_") or field.GetArray(index) is None:
            continue  # also the input's field data (a LAS file's 3-component LAS_Scale, ...)
        count = field.GetArray(index).GetTuple1(0)
        if name != "Unestimated_Points" and count > 0:
            print("%-26s %d" % ("  " + name[len("Unestimated_"):].replace("_", " ").lower(), count))
    outliers = field.GetArray("Outlier_Points")
    if outliers is not None:
        # Flagged, and given the curvatures of the surface nearest to them.
        count = int(outliers.GetTuple1(0))
        print("%-26s %d (%.2f %%; Outlier 1)" % ("outliers", count, count * share))
    if estimated:
        # Surroundings_Threshold is each point's neighborhood radius, the
        # distance within which its Neighbor_Count neighbors lie.
        rows = (("Neighbor_Count", "Neighbor_Count", ""),
                ("Surroundings_Threshold", "neighborhood radius", "; Surroundings_Threshold, a length"),
                ("Plane_Distance_Threshold", "Plane_Distance_Threshold", ""))
        for name, label, note in rows:
            if data.GetArray(name) is None:
                continue
            print("%-26s %.6g (median%s)" % (label, numpy.median(array(name)[valid]), note))
    print("%-26s %.3f s" % ("filter time", seconds))
    for name, label in (("Coordinate_System", "coordinate system"), ("Length_Unit", "length unit")):
        declared = field.GetAbstractArray(name)
        if declared is not None and declared.GetNumberOfValues():
            text = declared.GetValue(0)
            print("%-26s %s" % (label, text if len(text) <= 60 else text[:57] + "..."))
    unit = field.GetAbstractArray("Curvature_Unit")
    if unit is not None and unit.GetNumberOfValues():
        # Lengths (radius, coordinates) are in the input's unit, curvatures in its inverse.
        print("%-26s %s (Gauss_Curvature: its square)" % ("curvature unit", unit.GetValue(0)))
    if not estimated:
        sys.stderr.write("estimate_curvatures: warning: no point was estimated (too few neighbors? "
                         "try a larger --radius or --neighbors)\n")
    print()
    print("%-26s %12s %12s %12s %12s %12s" % ("at estimated points", "min", "5 %", "median", "95 %", "max"))
    for name in CURVATURE_ARRAYS:
        print(percentiles_row(name, array(name)[valid]))

    if estimated and all(data.GetArray(name) is not None
                         for name in ("Exact_Minimum_Curvature", "Exact_Maximum_Curvature")):
        exact_min, exact_max = array("Exact_Minimum_Curvature"), array("Exact_Maximum_Curvature")
        scale = max(numpy.abs(exact_min).max(), numpy.abs(exact_max).max(), 1e-300)
        print()
        print("against the exact curvatures in the input (mean |k - exact| / max |exact|):")
        print("  k_min %.5f   k_max %.5f" % (
            numpy.abs(array("Minimum_Curvature")[valid] - exact_min[valid]).mean() / scale,
            numpy.abs(array("Maximum_Curvature")[valid] - exact_max[valid]).mean() / scale))


# ---------------------------------------------------------------------------
# Writing results


def write_vtp(curvatures, path, compress):
    """The filter's output as VTK XML polydata, compressed (zlib) if asked."""
    # Inline binary, not the default appended data: ParaView 5.11 with a
    # current Debian 12 libexpat (2.5.0-1+deb12u2 and later) cannot read
    # appended data (VTK issue 19258).
    written = time.time()
    writer = simple.XMLPolyDataWriter(Input=curvatures, FileName=path, DataMode="Binary",
                                      CompressorType="ZLib" if compress else "None")
    writer.UpdatePipeline()  # the writer reports failures only as VTK errors: check the file
    if not os.path.isfile(path) or os.path.getmtime(path) < written - 1.0:
        fail("could not write %s (see the messages above)" % path)


def write_las(curvatures, path):
    """The filter's output as LAS 1.4 through the plugin's writer; exits
    with the writer's message if it fails."""
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.vtkCommonCore import VTK_STRING

    errors = []

    @calldata_type(VTK_STRING)
    def keep(caller, event, message):
        errors.append(message.strip().splitlines()[-1].split("): ", 1)[-1])

    writer = simple.LASPointCloudWriter(Input=curvatures, FileName=path)
    writer.GetClientSideObject().AddObserver("ErrorEvent", keep)
    writer.UpdatePipeline()
    simple.Delete(writer)
    if errors or not os.path.isfile(path):
        fail("could not write %s: %s" % (path, "; ".join(errors) or "see the messages above"))


def float_keeps_points(points):
    """Whether float coordinates stay within a millionth of the cloud's size
    of the double ones (not so for coordinates far from the origin, such as
    a georeferenced scan's)."""
    import numpy

    if len(points) == 0:
        return True
    size = float(numpy.max(numpy.ptp(points, axis=0)))
    error = float(numpy.max(numpy.abs(points.astype(numpy.float32).astype(numpy.float64) - points)))
    return numpy.isfinite(size) and error <= 1e-6 * size


def write_points_file(cloud, normals, path, single=False):
    """The cloud (a data set in this process) as .ply or .csv, by path's
    extension, through the plugin's writers (PLY and CSV Point Cloud
    Writer, what SaveData picks): x y z, the normals array as nx ny nz,
    RGB as red green blue, every other array in its own type (vectors as
    <name>_x _y _z); with `single`, float points where float keeps them.
    Raises OSError when the writer fails (it prints why)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkCommonCore import VTK_DOUBLE

    points = cloud.GetPoints()
    as_float = bool(single and points is not None and points.GetDataType() == VTK_DOUBLE
                    and float_keeps_points(vtk_to_numpy(points.GetData()).reshape(-1, 3)))
    producer = producer_of(cloud)
    make = simple.PLYPointCloudWriter if path.lower().endswith(".ply") else simple.CSVPointCloudWriter
    writer = make(Input=producer, FileName=path, NormalsArray=normals or "", PointsAsFloat=int(as_float))
    try:
        writer.UpdatePipeline()
        # The proxy's object gathers MPI pieces; the VTK writer inside says
        # whether the file was written.
        if writer.GetClientSideObject().GetWriter().GetErrorCode():
            raise OSError("see the message above")
    finally:
        simple.Delete(writer)
        simple.Delete(producer)


def write_ply(cloud, normals, path, single=False):
    """The points and their arrays as a binary little-endian PLY vertex
    element (write_points_file)."""
    write_points_file(cloud, normals, path, single)


def write_csv(cloud, normals, path, single=False):
    """The points and their arrays as comma-separated text: a header line of
    the column names, one row per point, every value exact
    (write_points_file)."""
    write_points_file(cloud, normals, path, single)


def write_output(curvatures, result, normals, path, compress=False, single=False):
    """Writes the filter's output (result, fetched) in the format of path's
    extension (.vtp, .ply, .csv, .las), a .vtp compressed with `compress`; exits
    with a message if that fails."""
    extension = os.path.splitext(path)[1].lower()
    if extension == ".vtp":
        write_vtp(curvatures, path, compress)
        return
    if extension == ".las":
        write_las(curvatures, path)
        return
    try:
        if extension == ".ply":
            write_ply(result, normals, path, single)
        else:
            write_csv(result, normals, path, single)
    except (OSError, ValueError) as error:
        fail("could not write %s: %s" % (path, error))


def main(argv):
    # pvpython's sys.stdout and sys.stderr send text through VTK's output
    # window (for the GUI's message window), which plain_vtk_messages
    # silences: a command-line tool writes to the streams themselves.
    sys.stdout, sys.stderr = sys.__stdout__, sys.__stderr__
    arguments = parse_arguments(argv)
    output_folder = os.path.dirname(os.path.abspath(arguments.output))
    if not os.path.isdir(output_folder):
        fail("the output's folder does not exist: %s" % output_folder)
    progress = Progress(arguments.progress)
    plain_vtk_messages()
    load_plugin(arguments.plugin)
    progress.begin("reading %s" % arguments.input)
    source = open_cloud(arguments.input)
    if arguments.normals and arguments.estimate_normals:
        fail("--normals and --estimate-normals exclude each other")
    normals = None if arguments.estimate_normals else choose_normals(source, arguments.normals)

    curvatures = simple.PrincipalCurvatures(Input=source)
    normals_description = configure_normals(curvatures, arguments, normals)
    configure(curvatures, arguments)
    progress.begin("estimating normals and curvatures" if curvatures.NormalsSource == "Estimated"
                   else "estimating curvatures")
    progress.watch(curvatures)
    start = time.perf_counter()
    curvatures.UpdatePipeline()
    seconds = time.perf_counter() - start
    progress.end()

    result = servermanager.Fetch(curvatures)
    if result is None or result.GetPointData().GetArray("Curvature_Valid") is None:
        fail("the filter produced no curvatures (see the messages above)")
    used = "Normals" if normals is None or arguments.estimate_normals else normals
    progress.begin("writing %s" % arguments.output)
    # Asked for a small file: a .vtp is compressed too.
    write_output(curvatures, result, used, arguments.output,
                 compress=arguments.single_precision or arguments.no_diagnostics,
                 single=arguments.single_precision)
    progress.end()

    lines = None
    if arguments.lines:
        progress.begin("finding the curvature lines")
        lines_proxy = lines_filter(curvatures, arguments.line_kinds)
        progress.watch(lines_proxy)
        lines_proxy.UpdatePipeline()
        progress.end()
        lines = servermanager.Fetch(lines_proxy)
        progress.begin("writing %s" % arguments.lines)
        try:
            write_lines(lines_proxy, lines, arguments.lines)
        except OSError as error:
            fail("could not write %s: %s" % (arguments.lines, error))
        progress.end()

    summarize(result, seconds, [
        ("input", arguments.input),
        ("normals", normals_description),
        ("fit mode", arguments.fit_mode),
        ("neighborhood", neighborhood_description(curvatures)),
    ])
    if lines is not None:
        summarize_lines(lines)
    print()
    print("wrote %s" % arguments.output)
    if lines is not None:
        print("wrote %s" % arguments.lines)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
