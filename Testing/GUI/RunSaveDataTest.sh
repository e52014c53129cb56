#!/usr/bin/env bash
# File > Save Data in the real GUI under Xvfb, through its dialogs: a
# georeferenced sphere (x y z near 637180, 4100000) run through the filter
# (gui_script.py), then Ctrl+S, the file name typed into the Save File
# dialog, Enter, and Enter on the writer's settings dialog if one shows;
# once as .ply and once as .csv. The files must come from the plugin's
# writers: the PLY with double x y z and the curvature arrays, the CSV with
# every digit of the coordinates (ParaView's own writers give float x y z
# and 6.3718e+05).
#   RunSaveDataTest.sh PARAVIEW PLUGIN SCREENSHOT.png
set -u
paraview=$1 plugin=$2 screenshot=$3
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
# A 2-unit sphere of 3000 points whose first point is (637180.123456,
# 4100000.654321, 14.25), digits that 5 significant ones would lose.
awk 'BEGIN { n = 3000; pi = atan2(0, -1)
  printf "637180.123456 4100000.654321 14.25\n"
  for (i = 1; i < n; ++i) { z = 1 - 2 * (i + 0.5) / n; r = sqrt(1 - z * z); phi = (i + 0.5) * pi * (3 - sqrt(5))
    printf "%.10f %.10f %.10f\n", 637180.123456 + 2 * r * cos(phi), 4100000.654321 + 2 * r * sin(phi), 12.25 + 2 * z } }' \
  > "$work/sphere.xyz"
export GUI_TEST_PLUGIN=$plugin GUI_TEST_CLOUD=$work/sphere.xyz

saved_or_asked() {
  [ -s "$1" ] || gui_visible "Configure Writer"
}
gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER"
  gui_place_window
  for extension in ply csv; do
    if ! gui_type_in_dialog "Save File" ctrl+s "$work/saved.$extension"; then
      echo "no Save File dialog for .$extension" >> "$work/events"
      continue
    fi
    # Saved, or the writer's settings asked for first.
    gui_until 60 saved_or_asked "$work/saved.$extension"
    gui_wait_still
    [ "$extension" = ply ] && gui_capture "$screenshot"
    if gui_visible "Configure Writer"; then
      xdotool key Return
      gui_until 60 test -s "$work/saved.$extension"
      gui_wait_still
    fi
  done
}
gui_run "$paraview" --dr --script="$here/gui_script.py"

status=0
gui_read_marker 'ok*' || status=1
[ -s "$work/events" ] && { echo "FAILED: $(cat "$work/events")"; status=1; }
header=$(sed -n '1,/^end_header/p' "$work/saved.ply" 2>/dev/null | tr -d '\0')
for line in "comment written by the PrincipalCurvatures plugin (vtkPLYPointCloudWriter)" \
  "property double x" "property double Mean_Curvature" "property double Maximum_Curvature_Direction_x" \
  "comment array Maximum_Curvature_Direction_x 3 Maximum_Curvature_Direction"; do
  if grep -qxF "$line" <<< "$header"; then
    echo "saved.ply: $line"
  else
    echo "FAILED: saved.ply has no line '$line'"
    status=1
  fi
done
first=$(sed -n 2p "$work/saved.csv" 2>/dev/null)
names=$(sed -n 1p "$work/saved.csv" 2>/dev/null)
case "$names" in x,y,z,*Mean_Curvature*) echo "saved.csv: header ${names:0:60}..." ;;
  *) echo "FAILED: saved.csv header '${names:0:80}'"; status=1 ;; esac
case "$first" in 637180.123456,4100000.654321,14.25,*) echo "saved.csv: first point ${first:0:40}..." ;;
  *) echo "FAILED: saved.csv first point '${first:0:80}' (every digit of 637180.123456 expected)"; status=1 ;; esac
[ $status -eq 0 ] && echo "File > Save Data used the plugin's writers"
exit $status
