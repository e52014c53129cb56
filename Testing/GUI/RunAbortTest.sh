#!/usr/bin/env bash
# Abort in the real ParaView GUI under Xvfb: a run of about a minute
# (abort_script.py), a real mouse click (xdotool) on the status bar's Abort
# button as soon as the run shows it enabled, and checks that the button was enabled (its red
# icon shows in the status bar), that the run returned after the click and
# short of its end (the progress it reported stayed below 0.9), and that the
# output is empty. How soon after the click it returned is printed, not
# checked: a loaded machine delays any process, and the promised second is
# measured by Benchmarks/abort_latency.py.
#   RunAbortTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin

# Captures the screen, and finds the enabled Abort button in it.
find_abort_button() {
  gui_capture "$screenshot"
  window=$(xdotool search --onlyvisible --name "ParaView" | head -n 1)
  [ -n "$window" ] || return 1
  eval "$(xdotool getwindowgeometry --shell "$window")"
  echo "window $X $Y $WIDTH $HEIGHT" > "$work/geometry"
  # The status bar: the bottom 30 rows of the window. The Abort button is
  # the only red there, and only while it is enabled.
  convert "$screenshot" -crop "${WIDTH}x30+${X}+$((Y + HEIGHT - 30))" +repage txt:- |
    awk -F"[(),: ]+" -v x0="$X" -v y0="$((Y + HEIGHT - 30))" '
      /^[0-9]/ { if ($3 > 180 && $4 < 90 && $5 < 90) { n++; sx += $1; sy += $2 } }
      END { if (n) printf "%d %d %d\n", x0 + sx / n, y0 + sy / n, n }' > "$work/button"
  [ -s "$work/button" ]
}
gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER.running"
  # Until the run has drawn its enabled Abort button, or has ended.
  gui_until 60 eval 'find_abort_button || [ -s "$GUI_TEST_MARKER" ]'
  if [ -s "$work/button" ]; then
    read -r bx by pixels < "$work/button"
    xdotool mousemove "$bx" "$by"
    # The click lies between these two times. xdotool click waits its
    # --delay (100 ms unless given) after the last click too, and the
    # driver shares the cores with the run: the run may return, and the GUI
    # log it, before the second time is taken.
    date +%s.%N > "$work/clicking"
    xdotool click --delay 0 1
    date +%s.%N > "$work/clicked"
  fi
  gui_wait_for "$GUI_TEST_MARKER"
}
gui_run "$paraview" --dr --script="$here/abort_script.py"

status=0
gui_read_marker 'ok*' || status=1
cat "$work/geometry" 2>/dev/null
if [ -s "$work/button" ]; then
  read -r bx by pixels < "$work/button"
  echo "Abort button enabled: $pixels red pixels in the status bar, clicked at $bx $by"
else
  echo "FAILED: no enabled (red) Abort button in the status bar during the run"
  exit 1
fi
# The click lies between "clicking" and "clicked". The run must return
# after "clicking" (a run that returned before the click was not stopped
# by it) and short of its end; the delay is reported.
returned=$(sed -n 's/^ok returned \([0-9.]*\) .*/\1/p' <<< "$marker")
reached=$(sed -n 's/^ok .* reached \([0-9.]*\),.*/\1/p' <<< "$marker")
clicking=$(cat "$work/clicking" 2>/dev/null)
clicked=$(cat "$work/clicked" 2>/dev/null)
if awk -v r="$returned" -v a="$clicking" -v b="$clicked" -v p="$reached" 'BEGIN {
    if (r == "" || a == "" || b == "" || p == "") { print "no return or click time, or no progress"; exit 1 }
    printf "the run returned %.3f s after the click began (xdotool took %.3f s), at progress %.3f\n", r - a, b - a, p
    exit !(r - a >= 0 && p < 0.9) }'; then
  :
else
  echo "FAILED: the run did not stop after the click, short of its end (or returned before the click)"
  status=1
fi
case "$marker" in *"output points 0"*) echo "the output is empty (aborted)" ;;
  *) echo "FAILED: the output is not empty"; status=1 ;; esac
echo "screenshot during the run: $screenshot"
exit $status
