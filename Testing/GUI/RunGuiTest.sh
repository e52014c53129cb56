#!/usr/bin/env bash
# The real ParaView GUI under Xvfb: load the plugin, open a normals-less
# .xyz, apply the filter with defaults and show it as a first Apply does,
# capture the whole screen, and check that it shows as points colored by
# the clipped mean curvature, (by OCR) that the filter's Properties panel is
# showing, and (by counting colors) that the view shows the colored cloud.
#   RunGuiTest.sh PARAVIEW PLUGIN CLOUD SCREENSHOT.png
set -u
paraview=$1 plugin=$2 cloud=$3 screenshot=$4
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin GUI_TEST_CLOUD=$cloud
gui_run "$paraview" --dr --script="$here/gui_script.py"

status=0
gui_read_marker 'ok*' || status=1
# A normals-less .xyz: read by the plugin's reader, normals estimated.
case "$marker" in *"reader ASCIIPointCloudReader, normals estimated True, colored by Mean_Curvature_Clipped, representation 'Points'"*) ;;
  *) echo "FAILED: the .xyz was not read by the plugin's reader with estimated normals and shown as points colored by Mean_Curvature_Clipped"; status=1 ;; esac
# The color bar says what the array is and its unit (the .xyz names none).
case "$marker" in *"color bar 'Mean curvature clipped (1/length unit)'"*) echo "color bar titled with the unit" ;;
  *) echo "FAILED: the color bar's title is not 'Mean curvature clipped (1/length unit)'"; status=1 ;; esac
# The color range is the clipped array's: symmetric about zero (white is
# zero curvature, although this torus's mean curvature is positive
# everywhere), its end the clip, at most a histogram bin (2^(1/16), 4.4 %)
# beyond the largest |mean curvature|.
read -r low high mean_low mean_high <<< "$(sed -n 's/.*color range \([^ ]*\) \([^,]*\), mean curvature \([^ ]*\) \([^,]*\),.*/\1 \2 \3 \4/p' <<< "$marker")"
if awk -v l="$low" -v h="$high" -v ml="$mean_low" -v mh="$mean_high" 'BEGIN {
    m = (mh > -ml) ? mh : -ml; d = l + h; if (d < 0) d = -d
    exit !(h > 0 && d <= 1e-6 * h && h <= 1.05 * m) }'; then
  echo "color range $low $high symmetric about zero (mean curvature $mean_low $mean_high)"
else
  echo "FAILED: color range '$low' '$high' not symmetric about zero (mean curvature '$mean_low' '$mean_high')"
  status=1
fi
gui_require_screenshot "$screenshot" || exit 1
# The left column (pipeline browser and Properties panel), enlarged: UI text
# is too small for OCR at screen size.
convert "$screenshot" -crop 300x1000+0+0 +repage -resize 300% -colorspace Gray "$work/panel.png"
text=$(tesseract "$work/panel.png" - 2>/dev/null)
[ -n "${GUI_TEST_DUMP_OCR:-}" ] && printf "%s\n" "$text" > "$GUI_TEST_DUMP_OCR"
for label in "Fit Mode" "Dynamic Adjustment" "Automatic Thresholds" "Neighborhood" "Fitting"; do
  if grep -q "$label" <<< "$text"; then
    echo "panel shows: $label"
  else
    echo "FAILED: the Properties panel does not show '$label'"
    status=1
  fi
done
# Settings the default mode (OrientedCircles, Automatic neighborhood) does
# not use are hidden. OCR wraps long labels ("Number Of" / "Neighbors"),
# and no other label shown by default has the word.
if grep -qi "Neighbors" <<< "$text"; then
  echo "FAILED: the panel shows 'Number Of Neighbors', which the default mode does not use"
  status=1
else
  echo "panel hides: Number Of Neighbors"
fi
grep -q "PrincipalCurvatures1" <<< "$text" && echo "pipeline browser shows PrincipalCurvatures1" ||
  { echo "FAILED: no PrincipalCurvatures1 in the pipeline browser"; status=1; }
# The render view (right of the panels): the cloud colored by curvature
# shows many colors; an uncolored or empty view has a handful.
colors=$(convert "$screenshot" -crop 1000x700+500+150 +repage -unique-colors -format "%w" info: 2>/dev/null || echo 0)
if [ "${colors:-0}" -gt 50 ]; then
  echo "render view shows $colors colors"
else
  echo "FAILED: the render view shows $colors colors (no colored cloud?)"
  status=1
fi
echo "screenshot: $screenshot"
exit $status
