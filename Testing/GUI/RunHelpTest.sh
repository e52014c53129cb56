#!/usr/bin/env bash
# The "?" of the Properties panel, in the real ParaView GUI under Xvfb: with
# Principal Curvatures the active source (help_script.py), a real click on
# the panel's "?" button (found right of the Delete button, located by OCR)
# must open ParaView's help window on the plugin's own page for the filter
# (pqHelpReaction::showProxyHelp finds it in the plugin's Qt help), not on
# ParaView's front page: the help window's text, read back by OCR, must
# hold the page's title, its sign convention and output array names. The
# panel's Normals row, on a cloud without normals, reads "None (automatic)"
# without ParaView's red no-entry icon (pqNormalsArraySelector): no red
# pixel in that row.
#   RunHelpTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin

gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER"
  if gui_place_window; then
    gui_capture "$work/before.png"
    # The panel buttons Apply, Reset, Delete, ?: the word Delete by OCR
    # (tsv: left top width height of each word), at three times the size.
    convert "$work/before.png" -crop 500x1000+0+0 +repage -resize 300% -colorspace Gray "$work/left.png"
    tesseract "$work/left.png" - tsv 2>/dev/null |
      awk -F "\t" '$12 == "Delete" { print int(($7 + $9) / 3), int(($8 + $10 / 2) / 3); exit }' \
      > "$work/delete"
    # The row of "(automatic)", by OCR too: its top and height.
    tesseract "$work/left.png" - tsv 2>/dev/null |
      awk -F "\t" '$12 == "(automatic)" { print int($8 / 3), int($10 / 3); exit }' \
      > "$work/automatic"
    read -r dx dy < "$work/delete"
    if [ -n "${dx:-}" ]; then
      # The "?" button: right of the Delete button, whose text ends about
      # 12 pixels before its edge; the ? button is about 26 pixels wide.
      echo "$dx $dy" > "$work/clicked"
      xdotool mousemove $((dx + 27)) "$dy" click 1
      if gui_place_window "Online Help"; then
        gui_capture "$screenshot"
        echo found > "$work/help_window"
      fi
    fi
  fi
  [ -s "$screenshot" ] || gui_capture "$screenshot"
}
gui_run "$paraview" --dr --script="$here/help_script.py"

status=0
gui_read_marker 'ready*' || exit 1
# The Normals row: the strip of the panel's width through "(automatic)".
read -r ay ah < "$work/automatic" 2> /dev/null
if [ -n "${ay:-}" ]; then
  convert "$work/before.png" -crop "500x$((ah + 8))+0+$((ay - 4))" +repage \
    "${screenshot%.png}_normals_row.png"
  red=$(gui_count_pixels "${screenshot%.png}_normals_row.png" "" "(r > 180) & (g < 90) & (b < 90)")
  if [ "$red" -eq 0 ]; then
    echo "the Normals row reads None (automatic), with no red icon"
  else
    echo "FAILED: $red red pixels in the Normals row (ParaView's no-entry icon)"
    status=1
  fi
else
  echo "FAILED: no '(automatic)' found by OCR in the Properties panel"
  status=1
fi
if [ -s "$work/clicked" ]; then
  echo "clicked the ? right of Delete at $(cat "$work/clicked")"
else
  echo "FAILED: no Delete button found by OCR in the Properties panel"
  exit 1
fi
if [ ! -s "$work/help_window" ]; then
  echo "FAILED: no help window opened"
  exit 1
fi
# The help window's page, enlarged for OCR.
convert "$screenshot" -resize 200% -colorspace Gray "$work/help.png"
text=$(tesseract "$work/help.png" - 2>/dev/null)
[ -n "${GUI_TEST_DUMP_OCR:-}" ] && printf "%s\n" "$text" > "$GUI_TEST_DUMP_OCR"
for phrase in "PrincipalCurvatureEstimation" "Sign convention" "bends away from the" \
    "Mean_Curvature_Clipped" "Maximum_Curvature_Direction"; do
  if grep -q "$phrase" <<< "$text"; then
    echo "help page shows: $phrase"
  else
    echo "FAILED: the help window does not show '$phrase' (not the filter's page?)"
    status=1
  fi
done
echo "screenshot: $screenshot"
exit $status
