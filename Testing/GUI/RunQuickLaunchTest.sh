#!/usr/bin/env bash
# The real ParaView GUI under Xvfb: bad .xyz files open and show without a
# crash (quick_launch_script.py); then, with a cloud selected, Ctrl+Space,
# "principal", Enter must create Principal Curvatures, not ParaView's
# Principal Component Analysis. ParaView 5.11's quick launch lists the
# labels that start with the typed words in the order of their characters
# and selects the first enabled one (pqQuickLaunchDialog::updateSearch); the
# pipeline browser is read back by OCR.
#   RunQuickLaunchTest.sh PARAVIEW PLUGIN CLOUD SCREENSHOT.png
set -u
paraview=$1 plugin=$2 cloud=$3 screenshot=$4
source "$(dirname "$0")/GuiHarness.sh"
gui_init "$screenshot"
export GUI_TEST_PLUGIN=$plugin GUI_TEST_CLOUD=$cloud

gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER"
  if gui_place_window; then
    gui_quick_launch "principal"
    gui_wait_still
  fi
  gui_capture "$screenshot"
}
gui_run "$paraview" --dr --script="$here/quick_launch_script.py"

status=0
gui_read_marker 'ready*Normals*' || { status=1; echo "FAILED: no cloud with normals"; }
# Bad text clouds (empty, two columns, words) opened and shown in the GUI
# by the plugin's reader, with the GUI still running afterwards.
case "$marker" in *"bad files read by ASCIIPointCloudReader ASCIIPointCloudReader ASCIIPointCloudReader"*)
  echo "bad .xyz files: read by the plugin's reader, shown, no crash" ;;
  *) status=1; echo "FAILED: bad .xyz files not read by the plugin's reader (or the GUI died)" ;; esac
gui_require_screenshot "$screenshot" || exit 1
# The pipeline browser (top left), enlarged for OCR.
convert "$screenshot" -crop 300x300+0+0 +repage -resize 300% -colorspace Gray "$work/browser.png"
text=$(tesseract "$work/browser.png" - 2>/dev/null)
[ -n "${GUI_TEST_DUMP_OCR:-}" ] && printf "%s\n" "$text" > "$GUI_TEST_DUMP_OCR"
if grep -q "PrincipalCurvatures1" <<< "$text"; then
  echo "quick launch 'principal' created PrincipalCurvatures1"
else
  echo "FAILED: quick launch 'principal' did not create PrincipalCurvatures1"
  status=1
fi
if grep -qi "Component" <<< "$text"; then
  echo "FAILED: quick launch 'principal' created Principal Component Analysis"
  status=1
fi
echo "screenshot: $screenshot"
exit $status
