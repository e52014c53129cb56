#!/usr/bin/env bash
# Recoloring a LAS cloud in the real ParaView GUI under Xvfb (files written
# by recolor_script.py, opened by File > Open and Apply as a user does):
# - tile.las opens in its true colors (RGB, Map Scalars off, no scalar bar);
#   colored by Classification it goes through the color map (Map Scalars
#   on), and the view shows the map's blues and reds, not the gray levels
#   or black that Map Scalars off makes of a classification; colored by RGB
#   again it is back in true colors;
# - zero.las, whose colors are all 0, is not colored by them (solid color);
# - result.las, tile.las through the filter and saved by the plugin's LAS
#   writer, opens in true colors and, colored by Mean_Curvature, shows the
#   map's colors under a color bar titled with the unit the tile's
#   coordinate system gives (metre), its NaN color named and counted for
#   the points not estimated (the lone point among them).
#   RunRecolorTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin

# Opens and applies a file of $work, and waits until the view has
# rendered it.
open_and_apply() {
  gui_open_and_apply "$work/$1" "^file $1 "
}
# Asks the GUI script for a change ("NAME color ARRAY", "NAME hide"), waits
# until the state shows a line matching PATTERN (or, for "-NAME", no line
# of NAME), and keeps the state as $work/state_TAG.
shows() {
  case "$1" in -*) ! grep -q "^file ${1#-} " "$work/state" ;; *) grep -qx "$1" "$work/state" ;; esac
}
request() {
  gui_mark_screen
  echo "$1" > "$work/request"
  gui_until 60 shows "$2" || echo "state never showed '$2' after '$1'" >> "$work/events"
  gui_wait_still
  cp "$work/state" "$work/state_$3"
}
gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER"
  grep -q "^ready" "$GUI_TEST_MARKER" && gui_place_window || return
  open_and_apply tile.las
  cp "$work/state" "$work/state_opened"
  request "tile.las color Classification" "file tile.las colored_by Classification.*" classes
  gui_capture "$work/classes.png"
  request "tile.las color RGB" "file tile.las colored_by RGB.*" colors
  request "tile.las hide" -tile.las hidden
  open_and_apply zero.las
  cp "$work/state" "$work/state_zero"
  request "zero.las hide" -zero.las hidden
  open_and_apply result.las
  cp "$work/state" "$work/state_result"
  request "result.las color Mean_Curvature" "file result.las colored_by Mean_Curvature.*" curvature
  gui_capture "$screenshot"
}
gui_run "$paraview" --dr --script="$here/recolor_script.py"

status=0
gui_read_marker 'ready*' || exit 1
gui_report_events
for tag in opened classes colors zero result curvature; do
  echo "state $tag: $(cat "$work/state_$tag" 2>/dev/null)"
done
state=$(cat "$work/state_opened" 2>/dev/null)
expect "file tile.las colored_by RGB map_scalars 0 scalar_bar 0.*"
state=$(cat "$work/state_classes" 2>/dev/null)
expect "file tile.las colored_by Classification map_scalars 1 scalar_bar [01].*"
state=$(cat "$work/state_colors" 2>/dev/null)
expect "file tile.las colored_by RGB map_scalars 0 scalar_bar 0.*"
state=$(cat "$work/state_zero" 2>/dev/null)
expect "file zero.las colored_by - map_scalars [01] scalar_bar 0.*"
state=$(cat "$work/state_result" 2>/dev/null)
expect "file result.las colored_by RGB map_scalars 0 scalar_bar 0.*"
state=$(cat "$work/state_curvature" 2>/dev/null)
expect "file result.las colored_by Mean_Curvature map_scalars 1 scalar_bar [01] title Mean curvature (1/metre) | nan not estimated ([1-9][0-9]*)"

# The middle of the render view, inside its frame (whose blue border would
# count): blues and reds of the map, far from gray.
view_colors() {
  gui_count_pixels "$1" "-crop 600x500+650+330 +repage" \
    "(b > r + 60) & (b > g + 30)" "(r > b + 60) & (r > g + 60)"
}
for picture in "$work/classes.png" "$screenshot"; do
  [ -s "$picture" ] || { echo "FAILED: no capture $picture"; status=1; continue; }
  read -r blues reds <<< "$(view_colors "$picture")"
  if [ "${blues:-0}" -gt 200 ] && [ "${reds:-0}" -gt 200 ]; then
    echo "$(basename "$picture"): the map's colors, $blues blue and $reds red pixels"
  else
    echo "FAILED: $(basename "$picture") shows ${blues:-0} blue and ${reds:-0} red pixels: not mapped colors"
    status=1
  fi
done
echo "screenshot: $screenshot"
exit $status
