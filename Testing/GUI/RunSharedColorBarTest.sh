#!/usr/bin/env bash
# Two clouds colored by the same array in one view, in the real ParaView
# GUI under Xvfb (shared_colorbar_script.py): they must share one color map
# whose range covers both clouds' Mean_Curvature_Clipped, and the view must
# show one scalar bar ("Mean curvature clipped (1/length unit)"), not two
# with different ranges.
#   RunSharedColorBarTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin
gui_run "$paraview" --dr --script="$here/shared_colorbar_script.py"

status=0
gui_read_marker 'ok*' || exit 1
maps=$(grep "^cloud " <<< "$marker" | awk '{ print $4 }' | sort -u | wc -l)
if [ "$maps" -eq 1 ]; then
  echo "two clouds in one view, one color map"
else
  echo "FAILED: $maps color maps for two clouds in one view"
  status=1
fi
# The map's range covers each cloud's data range.
while read -r _ name _ map _ low high _ data_low data_high; do
  if awk -v l="$low" -v h="$high" -v dl="$data_low" -v dh="$data_high" 'BEGIN {
      s = (h - l) * 1e-6; exit !(l <= dl + s && h >= dh - s) }'; then
    echo "cloud $name: map $map range $low $high covers its data $data_low $data_high"
  else
    echo "FAILED: cloud $name: map $map range $low $high does not cover its data $data_low $data_high"
    status=1
  fi
done < <(grep "^cloud " <<< "$marker")
bars=$(grep "^visible bars" <<< "$marker")
case "$bars" in "visible bars 1 titled Mean curvature clipped (1/length unit)"*) echo "one scalar bar: $bars" ;;
  *) echo "FAILED: not one scalar bar titled Mean curvature clipped (1/length unit): $bars"; status=1 ;; esac
echo "screenshot: $screenshot"
exit $status
