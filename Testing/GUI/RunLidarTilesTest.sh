#!/usr/bin/env bash
# Two colored LAS tiles 5 km apart, in the real ParaView GUI under Xvfb,
# as a user opens them: File > Open (Ctrl+O, the path typed, Enter), then
# Apply (Alt+A), for one tile, then the other. Checks (from the state
# lidar_tiles_script.py records after each render):
# - both tiles lie wholly in the view: the second did not land off-screen
#   (ParaView resets the camera only for the first data in a view);
# - each tile is colored by its RGB with Map Scalars off (true colors) and
#   no scalar bar;
# and on the captured screen, that the view shows pure red and pure green
# points (the tiles' colors), not colors of a map.
#   RunLidarTilesTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin

# Opens and applies a tile, and waits until the view has rendered it.
open_and_apply() {
  gui_open_and_apply "$1" "^tile $(basename "$1") "
}
gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER"
  gui_place_window || return
  open_and_apply "$work/tile_west.las"
  cp "$work/state" "$work/state_first" 2>/dev/null
  open_and_apply "$work/tile_east.las"
  gui_capture "$screenshot"
}
gui_run "$paraview" --dr --script="$here/lidar_tiles_script.py"

status=0
gui_read_marker 'ready*' || exit 1
gui_report_events
echo "after the first tile:"
sed "s/^/  /" "$work/state_first" 2>/dev/null
echo "after the second tile:"
sed "s/^/  /" "$work/state" 2>/dev/null
state=$(cat "$work/state" 2>/dev/null)
for tile in tile_west.las tile_east.las; do
  line=$(grep "^tile $tile " <<< "$state")
  if [ -z "$line" ]; then
    echo "FAILED: $tile is not shown"
    status=1
    continue
  fi
  case "$line" in *"in_view 1 "*) echo "$tile wholly in view" ;;
    *) echo "FAILED: $tile not wholly in view (off-screen)"; status=1 ;; esac
  case "$line" in *"colored_by RGB map_scalars 0 scalar_bar 0"*) echo "$tile in true colors (RGB, Map Scalars off), no scalar bar" ;;
    *) echo "FAILED: $tile not in true colors with no scalar bar: $line"; status=1 ;; esac
done
gui_require_screenshot "$screenshot" || exit 1
# The render view (right of the panels): pure red and pure green points.
read -r reds greens <<< "$(gui_count_pixels "$screenshot" "-crop 1000x700+500+150 +repage" \
  "(r > 200) & (g < 40) & (b < 40)" "(g > 200) & (r < 40) & (b < 40)")"
if [ "${reds:-0}" -gt 200 ] && [ "${greens:-0}" -gt 200 ]; then
  echo "view shows the tiles' own colors: $reds pure red and $greens pure green pixels"
else
  echo "FAILED: view shows ${reds:-0} pure red and ${greens:-0} pure green pixels: not the tiles' colors"
  status=1
fi
echo "screenshot: $screenshot"
exit $status
