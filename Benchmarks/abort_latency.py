"""How responsive a run is, in seconds, as ParaView sees it: the largest gap
between two progress events (ParaView's GUI handles events, and Abort,
only at progress events), how soon the filter returns after an Abort
requested in each stage, and how right the time left announced half-way
is. The promise is a second for each; the tests check the behavior
(Testing/Python/TestProgressPython.py, whose ProgressLog this reuses) and
this program reports the times.

    pvpython Benchmarks/abort_latency.py PLUGIN.so [--runs 3]

Prints one line per measurement and the median over the runs.
"""

import argparse
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Testing", "Python"))

from paraview import simple  # noqa: E402
from TestProgressPython import ProgressLog, largest_gap, producer, time_left_half_way, torus  # noqa: E402

STAGES = [
    ("first serial steps", dict(abort_at=0.0, abort_below=0.01, abort_in_serial_stage=True)),
    ("plane fits", dict(abort_at=0.2, abort_below=0.3)),
    ("orientation", dict(abort_at=0.3, abort_below=0.4, abort_in_serial_stage=True)),
    ("curvatures' serial steps", dict(abort_at=0.4, abort_in_serial_stage=True, repeats=1)),
]


def full_run(source):
    curvatures = simple.PrincipalCurvatures(Input=source)
    log = ProgressLog(curvatures)
    start = time.perf_counter()
    curvatures.UpdatePipeline()
    finished = time.perf_counter()
    simple.Delete(curvatures)
    return finished - start, largest_gap(log, start, finished), time_left_half_way(log, finished)


def abort_delay(source, options):
    aborted = simple.PrincipalCurvatures(Input=source)
    log = ProgressLog(aborted, **options)
    aborted.UpdatePipeline()
    returned = time.perf_counter()
    simple.Delete(aborted)
    return None if log.abort_time is None else returned - log.abort_time


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("plugin")
    parser.add_argument("--runs", type=int, default=3)
    arguments = parser.parse_args()
    simple.LoadPlugin(arguments.plugin, remote=False)
    source = producer(torus(2000000))
    gaps, delays = [], {stage: [] for stage, _ in STAGES}
    for run in range(arguments.runs):
        seconds, gap, half_way = full_run(source)
        gaps.append(gap)
        said = "no time left said past half-way" if half_way is None else \
            "at %.0f %% it said %d s left, %.1f s remained" % (100 * half_way[0], half_way[1], half_way[2])
        print("run %d: 2M points, defaults, %.2f s; largest gap between progress events %.3f s; %s"
              % (run + 1, seconds, gap, said))
        for stage, options in STAGES:
            delay = abort_delay(source, options)
            if delay is not None:
                delays[stage].append(delay)
            print("run %d: Abort in the %s: %s" % (run + 1, stage,
                  "no request made" if delay is None else "returned after %.3f s" % delay))
    print("median largest gap: %.3f s (promise: under 0.5 s)" % statistics.median(gaps))
    for stage, values in delays.items():
        if values:
            print("median Abort delay in the %s: %.3f s (promise: under 1 s)" % (stage, statistics.median(values)))


if __name__ == "__main__":
    main()
