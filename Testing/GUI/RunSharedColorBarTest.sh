#!/usr/bin/env bash
# Two clouds colored by the same array in one view, in the real ParaView
# GUI under Xvfb (shared_colorbar_script.py): they must share one color map
# whose range covers both clouds' Mean_Curvature_Clipped, and the view must
# show one scalar bar of that title, not two with different ranges.
#   RunSharedColorBarTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export GUI_TEST_PLUGIN=$plugin GUI_TEST_MARKER=$work/marker GUI_TEST_WORK=$work
mkdir -p "$(dirname "$screenshot")"
rm -f "$screenshot"

xvfb-run -a -s "-screen 0 1600x1000x24" bash -c '
  "$0" --dr --script="$1" > "$GUI_TEST_WORK/paraview.log" 2>&1 &
  pid=$!
  for i in $(seq 1 120); do [ -s "$GUI_TEST_MARKER" ] && break; sleep 1; done
  window=$(xdotool search --sync --onlyvisible --name "ParaView" | head -n 1)
  [ -n "$window" ] && xdotool windowmove "$window" 0 0 windowsize "$window" 1600 1000
  sleep 5
  import -window root "$2"
  kill "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  exit 0' "$paraview" "$here/shared_colorbar_script.py" "$screenshot"

status=0
marker=$(cat "$GUI_TEST_MARKER" 2>/dev/null || echo "no marker: the GUI script did not run")
echo "GUI script: $marker"
case "$marker" in ok*) ;; *) tail -n 20 "$work/paraview.log"; exit 1 ;; esac
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
case "$bars" in "visible bars 1 titled Mean_Curvature_Clipped"*) echo "one scalar bar: $bars" ;;
  *) echo "FAILED: not one scalar bar titled Mean_Curvature_Clipped: $bars"; status=1 ;; esac
echo "screenshot: $screenshot"
exit $status
