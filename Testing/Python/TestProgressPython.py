"""Live progress and Abort, as ParaView sees them:

    pvpython TestProgressPython.py PLUGIN.so

* a 600k-point torus without normals (normals estimated, then the
  curvatures) through PrincipalCurvatures with defaults: the filter's
  progress events arrive on the main thread (the only one ParaView listens
  to), at least ten of them strictly between 0 and 1, never going back, then
  1: ParaView's GUI handles events, and Abort, only at progress events;
* during that run the progress text (what ParaView's progress bar shows)
  names the filter and, once the pace is known, says the time left;
* the same with Abort requested from a progress event, as ParaView's Abort
  button does it, in the first serial steps, the parallel plane fits, the
  serial orientation of the normals and the curvatures' serial steps: the
  filter stops in that stage (its progress moves on by less than a tenth
  after the request, and not at all in a serial stage), with no output. A
  request is made only while the run is short of its end (progress below
  1); one that missed its stage (a serial stage ended before it, or was too
  short to be recognized) is checked the same way, then made again, up to
  three runs;
* Point Cloud Normals on a 2M-point torus (the normals alone are too quick
  on 600k for ten updates): progress on the main thread too.

Every check prints one line; the exit code is 0 when all pass, 1 otherwise.
No check reads the clock: how far apart the events are in seconds, how
soon an Abort returns and how right the time left is are measured by
Benchmarks/abort_latency.py, which reuses this file's ProgressLog.
"""

import re
import sys
import threading
import time

import numpy
from paraview import simple
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from test_checks import check, failures  # noqa: E402 (the tests' folder is on sys.path)

MAIN_THREAD = threading.get_ident()


def torus(count=600000, major=3.0, minor=1.0, seed=16):
    """Points uniformly random in the torus' two angles (fixed seed)."""
    generator = numpy.random.default_rng(seed)
    u, v = generator.uniform(0.0, 2.0 * numpy.pi, (2, count))
    ring = major + minor * numpy.cos(v)
    return numpy.column_stack([ring * numpy.cos(u), ring * numpy.sin(u), minor * numpy.sin(v)])


def producer(points):
    data = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(numpy.ascontiguousarray(points), deep=True))
    data.SetPoints(vtk_points)
    source = simple.TrivialProducer()
    source.GetClientSideObject().SetOutput(data)
    source.UpdatePipeline()
    return source


class ProgressLog:
    """The progress events of a filter: value, thread, time; optionally
    aborts the filter once the progress lies in [abort_at, abort_below)
    (always short of 1: at 1 the work is done, and a request then has
    nothing left to stop). With abort_in_serial_stage, the abort waits for
    `repeats` events in a row reporting the same progress: a serial stage,
    which is not counted."""

    def __init__(self, proxy, abort_at=None, abort_below=1.0, abort_in_serial_stage=False, repeats=2):
        self.algorithm = proxy.GetClientSideObject()
        self.events = []
        self.texts = []
        self.abort_at = abort_at
        self.abort_below = min(abort_below, 1.0)
        self.abort_in_serial_stage = abort_in_serial_stage
        self.repeats = repeats
        self.abort_time = None
        self.abort_value = None
        self.abort_event = None
        self.algorithm.AddObserver("ProgressEvent", self.on_progress)

    def in_range(self, progress):
        return self.abort_at <= progress < self.abort_below

    def in_serial_stage(self):
        """The last `repeats` events report the same progress, in the range
        aimed at: a stage that is not counted, such as the normals'
        orientation."""
        last = [value for value, _, _ in self.events[-self.repeats:]]
        return len(last) == self.repeats and len(set(last)) == 1 and self.in_range(last[0])

    def on_progress(self, algorithm, _event):
        progress = algorithm.GetProgress()
        self.events.append((progress, threading.get_ident(), time.perf_counter()))
        self.texts.append(algorithm.GetProgressText() or "")
        if self.abort_at is None or self.abort_time is not None:
            return
        if self.in_serial_stage() if self.abort_in_serial_stage else self.in_range(progress):
            self.abort_time = time.perf_counter()
            self.abort_value = progress
            self.abort_event = len(self.events) - 1
            algorithm.SetAbortExecute(1)

    def stopped_in_stage(self):
        """The request was made in the stage aimed at, and the run stopped
        there: for a serial stage, the progress did not move on between the
        request and the return (the pipeline's closing 1 aside); the core
        stores the progress it has reached on every check, so a request that
        came after the stage shows as a later progress."""
        if self.abort_event is None:
            return False
        after = [value for value, _, _ in self.events[self.abort_event + 1:] if value < 1.0]
        if not self.abort_in_serial_stage:
            return all(value < self.abort_value + 0.1 for value in after)
        return all(value == self.abort_value for value in after)

    def values(self):
        return [value for value, _, _ in self.events]

    def on_main_thread(self):
        return all(thread == MAIN_THREAD for _, thread, _ in self.events)


def largest_gap(log, start, finished):
    """The longest time in seconds between two progress events (the start
    and the end included): reported by the benchmark, not checked."""
    times = [start] + [when for _, _, when in log.events] + [finished]
    return max(b - a for a, b in zip(times, times[1:]))


def check_progress(name, log):
    values = log.values()
    inner = [v for v in values if 0.0 < v < 1.0]
    check(log.on_main_thread(), "%s: all %d progress events on the main thread" % (name, len(values)))
    check(len(inner) >= 10, "%s: %d progress updates strictly between 0 and 1 (at least 10)" % (name, len(inner)))
    check(all(b >= a for a, b in zip(values, values[1:])), "%s: the progress never goes back" % name)
    check(bool(values) and values[-1] == 1.0, "%s: the last progress is 1" % name)


TIME_LEFT = re.compile(r"^Principal curvatures: about (?:(\d+) h )?(\d+) (s|min) left$")
SHORT_TIME_LEFT = re.compile(r"^Principal curvatures: less than (\d+) s left$")


def seconds_left(text):
    """The time left a progress text announces, in seconds (at most that
    many for a short one); None without one."""
    short = SHORT_TIME_LEFT.match(text)
    if short:
        return int(short.group(1))
    match = TIME_LEFT.match(text)
    if not match:
        return None
    hours, amount, unit = match.group(1), int(match.group(2)), match.group(3)
    return (int(hours or 0) * 3600) + amount * (60 if unit == "min" else 1)


def time_left_half_way(log, finished):
    """(progress, announced seconds left, seconds the run then took) at the
    first text past half-way that says the time left; None without one."""
    for (value, _, when), text in zip(log.events, log.texts):
        estimate = seconds_left(text)
        if value >= 0.5 and estimate is not None:
            return value, estimate, finished - when
    return None


def check_time_left(log):
    """The progress text names the filter and says the time left."""
    announced = [(value, when, seconds_left(text))
                 for (value, _, when), text in zip(log.events, log.texts)]
    with_estimate = [entry for entry in announced if entry[2] is not None]
    # The executive's first event (progress 0) comes before the filter runs.
    unnamed = [text for text in log.texts[1:] if not text.startswith("Principal curvatures")]
    check(not unnamed, "every progress text after the first names the filter, as %r (not %r)"
          % (log.texts[len(log.texts) // 2] if log.texts else None, unnamed[:3]))
    check(len(with_estimate) >= 5, "%d progress texts say the time left (at least 5)" % len(with_estimate))
    check(any(entry[0] >= 0.5 for entry in with_estimate), "the time left is said past half-way too")


def check_abort(stage, log_options, source, attempts=3):
    """Abort requested from a progress event in `stage`: the filter returns
    in that stage, with no output. Every run in which Abort was requested
    is checked so, whether or not the request came in `stage`; a run that
    stopped so but not in `stage` (the stage was shorter than the events'
    spacing, or ended just after the request), or in which no request was
    made, is made again, at most `attempts` runs."""
    for attempt in range(1, attempts + 1):
        aborted = simple.PrincipalCurvatures(Input=source)
        abort_log = ProgressLog(aborted, **log_options)
        aborted.UpdatePipeline()
        run = "Abort in the %s (run %d)" % (stage, attempt)
        requested = abort_log.abort_time is not None
        honored = True
        if requested:
            honored = check(aborted.GetDataInformation().GetNumberOfPoints() == 0,
                             "%s, requested at progress %.3f: no output" % (run, abort_log.abort_value))
        check(abort_log.on_main_thread(), "%s: progress on the main thread" % run)
        in_stage = abort_log.stopped_in_stage()
        simple.Delete(aborted)
        if in_stage or not honored:
            break
        missed = "stopped after the stage" if requested else "no request before the end"
        print("       %s: %s%s" % (run, missed, "; again" if attempt < attempts else ""))
    check(in_stage, "Abort requested, and the run stopped, in the %s (%d of at most %d runs)"
          % (stage, attempt, attempts))


def main(plugin):
    simple.LoadPlugin(plugin, remote=False)
    source = producer(torus())

    curvatures = simple.PrincipalCurvatures(Input=source)
    log = ProgressLog(curvatures)
    curvatures.UpdatePipeline()
    check_progress("PrincipalCurvatures on 600k points", log)
    check_time_left(log)
    check(curvatures.GetDataInformation().GetNumberOfPoints() == 600000, "the full run gives every point")

    # Serial stages report no progress of their own: their progress repeats.
    # A few tenths of a second each, a few events 0.1 s apart: the request
    # comes at the second (the first past 0.4 for the curvatures' serial
    # steps), early in the stage. The first serial steps (reading the cloud,
    # repeated points, the normals' radius and grid order) and the
    # orientation are too short on 600k points for two events since they
    # got faster, and so is the plane fits' window [0.2, 0.3) on a quiet
    # machine (a tenth of a second): they are aimed at on 2M.
    large = producer(torus(2000000))
    check_abort("first serial steps", dict(abort_at=0.0, abort_below=0.01, abort_in_serial_stage=True), large)
    check_abort("plane fits", dict(abort_at=0.2, abort_below=0.3), large)
    # The orientation reports the plane fits' end (0.36) until it is done.
    check_abort("orientation", dict(abort_at=0.3, abort_below=0.4, abort_in_serial_stage=True), large)
    # The curvatures' thresholds, grid and order, at the normals' end (0.45):
    # the orientation reports 0.36, the curvatures' parallel stage more than
    # 0.45.
    check_abort("curvatures' serial steps", dict(abort_at=0.4, abort_in_serial_stage=True, repeats=1), source)

    # The normals alone take well under a second on 600k points: a cloud
    # large enough for a run of a few seconds shows whether they report.
    normals = simple.PointCloudNormals(Input=large)
    normals_log = ProgressLog(normals)
    normals.UpdatePipeline()
    check_progress("PointCloudNormals on 2M points", normals_log)

    print("%d failed" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
