#!/usr/bin/env bash
# Curvature Lines in the real ParaView GUI under Xvfb, as a user gets them
# (curvature_lines_script.py opens a Gaussian bump): Apply (Alt+A), then
# Principal Curvatures and Curvature Lines each by the quick launch
# (Ctrl+Space, the label typed, Enter) and Apply. At that first Apply the
# lines must show over the curvatures' points (not replace them), colored
# by Line_Kind (cells) with a categorical map named after the kinds drawn
# (the default's ridges and valleys, not the four kinds not asked for), its
# legend shown and lines 3 pixels wide; on the captured screen, the ridge
# orange and valley green of that map, and the legend's names (tesseract).
# Lines of a plane, shown afterwards: none drawn, no colors, no legend.
#   RunCurvatureLinesTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin

# Applies, then waits until the view has rendered with a line of the
# state that matches PATTERN; with no PATTERN (nothing is sure to change),
# until the screen is still.
apply() {
  xdotool windowfocus --sync "$window"
  xdotool key --clearmodifiers alt+a
  if [ -n "${1:-}" ]; then
    gui_until 120 grep -q "$1" "$work/state"
  else
    gui_wait_still
  fi
}
gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER"
  if gui_place_window; then
    # The script's reader is not a modified proxy: Apply is disabled, and
    # the screen may not change.
    apply
    gui_quick_launch "principal"
    apply "^curvatures shown$"
    gui_quick_launch "curvature lines"
    apply "^lines shown"
    gui_wait_still
    gui_capture "$screenshot"
    cp "$work/state" "$work/state_lines"
    # Then lines of a plane: none, so no colors and no legend.
    echo "plane" > "$work/request"
    gui_until 120 test -s "$work/empty"
  fi
}
gui_run "$paraview" --dr --script="$here/curvature_lines_script.py"

status=0
gui_read_marker 'ready*' || exit 1
state=$(cat "$work/state_lines" 2>/dev/null)
echo "after the last Apply:"
sed "s/^/  /" <<< "$state"
expect "curvatures shown"
expect "colored by CELLS Line_Kind"
expect "line width 3"
expect "categorical 1"
expect "annotations 0,Ridge,1,Valley"
expect "legend 1"
grep -q "^lines shown [1-9]" <<< "$state" && echo "lines found and shown" ||
  { echo "FAILED: no lines shown"; status=1; }
state=$(cat "$work/empty" 2>/dev/null)
echo "lines of a plane: $state"
expect "empty lines 0 colored_by - legend 0"
gui_require_screenshot "$screenshot" || exit 1
# The render view (right of the panels) shows the ridge orange (1, 0.6, 0)
# and the valley green (0, 0.7, 0.35) of the kinds' map, which the
# curvatures' blue-white-red map has not.
read -r oranges greens <<< "$(gui_count_pixels "$screenshot" "-crop 1100x850+480+100 +repage" \
  "(r > 220) & (g > 120) & (g < 185) & (b < 50)" "(r < 50) & (g > 150) & (b > 60) & (b < 120)")"
if [ "${oranges:-0}" -gt 100 ] && [ "${greens:-0}" -gt 100 ]; then
  echo "screen: $oranges ridge-orange and $greens valley-green pixels"
else
  echo "FAILED: screen shows ${oranges:-0} ridge-orange and ${greens:-0} valley-green pixels"
  status=1
fi
# Tesseract reads the legend's "Ridge" as "Ridg" at the size the two entries
# are drawn (the tick after the name joins its e).
found=$(gui_read_words "$screenshot" "-crop 1100x850+480+100 +repage -resize 200%" 11 "Ridge?|Valley")
if [ "$(wc -w <<< "$found")" -eq 2 ]; then
  echo "legend read on screen: $found"
else
  echo "FAILED: the legend's Ridge and Valley are not on screen (read: $found)"
  status=1
fi
echo "screenshot: $screenshot"
exit $status
