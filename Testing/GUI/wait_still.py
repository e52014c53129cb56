"""Waits until the X screen ($DISPLAY) stops changing, for GuiHarness.sh's
gui_wait_still: captures (ImageMagick's import) compared in memory, which
is quicker than writing and comparing image files.

    wait_still.py LIMIT PIXELS [MARK]

With MARK (a raw RGB capture, `import -window root -depth 8 rgb:MARK`),
first waits until the screen differs from it in more than PIXELS pixels;
then until three captures in a row differ in at most PIXELS pixels (a
blinking text cursor's). Gives up after LIMIT seconds; exits 0 either way:
the test's own checks then tell what the screen shows."""

import os
import subprocess
import sys
import time

import numpy

PAUSE = 0.2


def capture():
    data = subprocess.run(["import", "-window", "root", "-depth", "8", "rgb:-"],
                          stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=False).stdout
    return numpy.frombuffer(data, numpy.uint8).reshape(-1, 3) if data else None


def changed_pixels(a, b):
    if a is None or b is None or a.shape != b.shape:
        return sys.maxsize
    return int(numpy.count_nonzero((a != b).any(axis=1)))


def main():
    limit, pixels = float(sys.argv[1]), int(sys.argv[2])
    end = time.monotonic() + limit
    previous = capture()
    if len(sys.argv) > 3 and os.path.exists(sys.argv[3]):
        with open(sys.argv[3], "rb") as handle:
            mark = numpy.frombuffer(handle.read(), numpy.uint8).reshape(-1, 3)
        while changed_pixels(mark, previous) <= pixels and time.monotonic() < end:
            time.sleep(PAUSE)
            previous = capture()
    quiet = 0
    while quiet < 2 and time.monotonic() < end:
        time.sleep(PAUSE)
        current = capture()
        quiet = quiet + 1 if changed_pixels(previous, current) <= pixels else 0
        previous = current


main()
