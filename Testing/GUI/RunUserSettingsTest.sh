#!/usr/bin/env bash
# The plugin's File > Open defaults (pqPointCloudReaderDefaults) with a
# user's own settings, in the real ParaView GUI under Xvfb (no --dr, HOME
# in a scratch folder): the user's settings already make ParaView's XYZ
# Reader the default for *.xyz. File > Open of a .xyz (through the open
# dialog) must keep the user's choice; then File > Exit (Ctrl+Q), on which
# ParaView saves the user's settings, must save the user's entry and none
# of the plugin's (a ParaView started without the plugin would otherwise
# look for its readers).
#   RunUserSettingsTest.sh PARAVIEW PLUGIN
set -u
paraview=$1 plugin=$2
source "$(dirname "$0")/GuiHarness.sh"
gui_init
export GUI_TEST_PLUGIN=$plugin
export HOME=$work/home XDG_CONFIG_HOME=$work/home/.config
settings=$XDG_CONFIG_HOME/ParaView/ParaView-UserSettings.json
mkdir -p "$(dirname "$settings")"
cat > "$settings" <<'JSON'
{
  "settings" : {
    "RepresentedArrayListSettings" : {
      "ReaderDetails" : [ "*.xyz", "XYZ molecule files", "xyzreader" ]
    }
  }
}
JSON

gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER"
  # The GUI drawn: the welcome dialog a first start with these settings
  # shows is up.
  gui_wait_still
  welcome=$(xdotool search --onlyvisible --name "Welcome to ParaView" | head -n 1)
  if [ -n "$welcome" ]; then
    xdotool windowfocus --sync "$welcome"
    xdotool key Escape
    gui_until 30 eval '! gui_visible "Welcome to ParaView"'
  fi
  window=$(xdotool search --onlyvisible --name "ParaView 5" | head -n 1)
  if [ -n "$window" ]; then
    gui_type_in_dialog "Open File" ctrl+o "$work/scan.xyz" &&
      gui_until 60 grep -q "/scan.xyz$" "$work/sources" && gui_wait_still
    xdotool windowfocus --sync "$window"
    xdotool key --clearmodifiers ctrl+q
  fi
  gui_wait_exit 60 || echo "ParaView did not quit" > "$work/not_quit"
}
# No --dr: the user's settings are read.
gui_run "$paraview" --script="$here/file_open_script.py"

status=0
gui_read_marker 'ready*' || exit 1
if grep -q "^xyzreader .*scan\.xyz$" "$work/sources" 2>/dev/null; then
  echo "scan.xyz opened with the user's default, the XYZ Reader"
else
  echo "FAILED: scan.xyz not opened with the user's default: $(cat "$work/sources" 2>/dev/null)"
  status=1
fi
if [ -e "$work/not_quit" ]; then
  echo "FAILED: ParaView did not quit on Ctrl+Q (settings not saved)"
  exit 1
fi
saved=$(tr -d " \t\n" < "$settings")
echo "saved ReaderDetails: $(grep -o '"ReaderDetails":\[[^]]*\]' <<< "$saved")"
if grep -q '"ReaderDetails":\["\*.xyz","XYZmoleculefiles","xyzreader"\]' <<< "$saved"; then
  echo "the user's entry saved, alone"
else
  echo "FAILED: the saved settings do not hold the user's entry alone"
  status=1
fi
if grep -q "PointCloudReader" <<< "$saved"; then
  echo "FAILED: the plugin's reader defaults were saved into the user's settings"
  status=1
fi
exit $status
