#!/usr/bin/env bash
# Shape_Class in the real ParaView GUI under Xvfb (shape_class_script.py):
# colored by it, a display's color map is categorical, with one legend
# entry per class named as Shape_Class_Names names it, distinct colors,
# and its legend shown; on the captured screen, the legend's class names
# are read back (tesseract) and the torus shows the dome and saddle colors.
#   RunShapeClassTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin
gui_run "$paraview" --dr --script="$here/shape_class_script.py"

gui_read_marker 'ok*' || exit 1
status=0
state=$marker
expect "colored by Shape_Class"
expect "own map 1"
expect "categorical 1"
expect "annotations 0,Undetermined,1,Flat,2,Dome,3,Cup,4,Ridge,5,Valley,6,Saddle"
expect "colors 21"
expect "distinct 7"
expect "legend 1"
grep -q "^classes .*2.*6" <<< "$marker" && echo "the torus has domes and saddles" ||
  { echo "FAILED: no domes and saddles on the torus"; status=1; }
gui_require_screenshot "$screenshot" || exit 1
# The screen shows the dome red (0.84, 0.15, 0.16) and the saddle green
# (0.20, 0.65, 0.25) of the categorical map, which no continuous map has.
read -r reds greens <<< "$(gui_count_pixels "$screenshot" "-sample 50%" \
  "(r > 190) & (g < 70) & (b < 70)" "(g > 140) & (r < 80) & (b < 90)")"
if [ "$reds" -gt 200 ] && [ "$greens" -gt 200 ]; then
  echo "screen: $reds dome-red and $greens saddle-green pixels"
else
  echo "FAILED: screen shows $reds dome-red and $greens saddle-green pixels"
  status=1
fi
# The legend, at the bottom right of the view in the 1600x1000 window: its
# seven class names read back (tesseract, on the legend enlarged).
found=$(gui_read_words "$screenshot" "-crop 240x330+1380+670 +repage -resize 300%" 6 \
  "Undetermined|Flat|Dome|Cup|Ridge|Valley|Saddle")
if [ "$(wc -w <<< "$found")" -eq 7 ]; then
  echo "legend read on screen: $found"
else
  echo "FAILED: the legend's seven class names are not on screen (read: $found)"
  status=1
fi
echo "screenshot: $screenshot"
exit $status
