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
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export GUI_TEST_PLUGIN=$plugin GUI_TEST_MARKER=$work/marker GUI_TEST_WORK=$work
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

xvfb-run -a -s "-screen 0 1600x1000x24" bash -c '
  "$0" --script="$1" > "$GUI_TEST_WORK/paraview.log" 2>&1 &
  pid=$!
  for i in $(seq 1 120); do [ -s "$GUI_TEST_MARKER" ] && break; sleep 1; done
  sleep 3
  # A first start with these settings shows the welcome dialog.
  welcome=$(xdotool search --onlyvisible --name "Welcome to ParaView" | head -n 1)
  if [ -n "$welcome" ]; then
    xdotool windowfocus --sync "$welcome"
    xdotool key Escape
    sleep 2
  fi
  window=$(xdotool search --onlyvisible --name "ParaView 5" | head -n 1)
  if [ -n "$window" ]; then
    xdotool windowfocus --sync "$window"
    xdotool key --clearmodifiers ctrl+o
    dialog=$(timeout 60 xdotool search --sync --onlyvisible --name "Open File" | head -n 1)
    if [ -n "$dialog" ]; then
      sleep 2
      xdotool type --delay 40 "$GUI_TEST_WORK/scan.xyz"
      sleep 1
      xdotool key Return
      sleep 6
    fi
    xdotool windowfocus --sync "$window"
    xdotool key --clearmodifiers ctrl+q
  fi
  for i in $(seq 1 60); do kill -0 "$pid" 2>/dev/null || break; sleep 1; done
  if kill -0 "$pid" 2>/dev/null; then
    echo "ParaView did not quit" > "$GUI_TEST_WORK/not_quit"
    kill "$pid"
  fi
  wait "$pid" 2>/dev/null
  exit 0' "$paraview" "$here/file_open_script.py"

status=0
marker=$(cat "$GUI_TEST_MARKER" 2>/dev/null || echo "no marker: the GUI script did not run")
echo "GUI script: $marker"
case "$marker" in ready*) ;; *) tail -n 20 "$work/paraview.log"; exit 1 ;; esac
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
