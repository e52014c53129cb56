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
  exit 0' "$paraview" "$here/colormap_script.py" "$screenshot"

status=0
marker=$(cat "$GUI_TEST_MARKER" 2>/dev/null || echo "no marker: the GUI script did not run")
echo "GUI script: $marker"
case "$marker" in ok*) ;; *) tail -n 20 "$work/paraview.log"; exit 1 ;; esac
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
if [ ! -s "$screenshot" ]; then
  echo "FAILED: no screenshot"
  exit 1
fi
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
