#!/usr/bin/env bash
# A color map per cloud, in the real ParaView GUI under Xvfb: three tori of
# very different scales applied one after the other in one session
# (colormap_script.py), each shown in its own view; checks that each
# display's color map spans its own cloud's Mean_Curvature_Clipped (not the
# first cloud's), and, on the captured screen, that the second and third
# views show both ends of the map (reds and blues), not one color.
#   RunColorMapTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin
gui_run "$paraview" --dr --script="$here/colormap_script.py"

status=0
gui_read_marker 'ok*' || exit 1
# Each display's map spans its own cloud's clipped mean curvature.
while read -r _ name _ scale _ _ _ _ map _ low high _ data_low data_high; do
  if awk -v l="$low" -v h="$high" -v dl="$data_low" -v dh="$data_high" 'BEGIN {
      s = dh - dl; exit !(s > 0 && (l - dl) ^ 2 < (1e-6 * s) ^ 2 && (h - dh) ^ 2 < (1e-6 * s) ^ 2) }'; then
    echo "cloud $name (scale $scale): color map $map spans its own range $low $high"
  else
    echo "FAILED: cloud $name (scale $scale): color map $map spans $low $high, its data $data_low $data_high"
    status=1
  fi
done < <(grep "^cloud " <<< "$marker")
maps=$(grep "^cloud " <<< "$marker" | awk '{ print $9 }' | sort -u | wc -l)
[ "$maps" -eq 3 ] && echo "three clouds, three color maps" || { echo "FAILED: $maps color maps for three clouds"; status=1; }
gui_require_screenshot "$screenshot" || exit 1
# The three views as ParaView 5.11 lays them out in the 1600x1000 window:
# the first top left, the second the whole right half, the third bottom
# left; the middle of each, sampled at half size. A pixel is red when red
# exceeds blue by 60, blue when blue exceeds red by 60 (the gray-blue
# background by less than 30): a cloud colored over its own range shows
# both, one in a map far too wide for it neither.
regions=("400x250+420+250" "500x500+1025+330" "400x250+420+650")
for view in 1 2 3; do
  read -r reds blues colors <<< "$(convert "$screenshot" -crop "${regions[$((view - 1))]}" +repage \
    -sample 50% txt:- | awk -F"[(),: ]+" '/^[0-9]/ { seen[$3 "," $4 "," $5] = 1
      if ($3 > $5 + 60) r++; else if ($5 > $3 + 60) b++ }
      END { printf "%d %d %d", r, b, length(seen) }')"
  if [ "$view" -eq 1 ] || { [ "$reds" -gt 100 ] && [ "$blues" -gt 100 ]; }; then
    echo "view $view: $reds red and $blues blue pixels, $colors colors"
  else
    echo "FAILED: view $view shows $reds red and $blues blue pixels, $colors colors: not a spread of the map"
    status=1
  fi
done
echo "screenshot: $screenshot"
exit $status
