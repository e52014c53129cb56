# shellcheck shell=bash
# The harness shared by the GUI tests (Run*Test.sh): a private X display,
# ParaView launched on it, the test's own steps (clicks, keys, captures)
# while it runs, and cleanup on every exit path. Sourced, not run.
#
# Usage, in a Run*Test.sh:
#
#   #!/usr/bin/env bash
#   # What the test checks, and its arguments.
#   #   RunXTest.sh PARAVIEW PLUGIN SCREENSHOT.png
#   set -u
#   paraview=$1 plugin=$2 screenshot=$3
#   source "$(dirname "$0")/GuiHarness.sh"
#   gui_init "$screenshot"              # $work, $here, GUI_TEST_WORK, GUI_TEST_MARKER
#   export GUI_TEST_PLUGIN=$plugin      # whatever the test's script reads
#   gui_drive() {                       # optional: the default is below
#     gui_wait_for "$GUI_TEST_MARKER" && gui_place_window
#     gui_capture "$screenshot"
#   }
#   gui_run "$paraview" --dr --script="$here/x_script.py"
#   status=0
#   gui_read_marker 'ok*' || exit 1     # prints "GUI script: <marker>"
#   ...checks on $marker, $work/*, the screenshot; set status=1 on a failure
#   exit $status
#
# What the harness provides:
#   gui_init [SCREENSHOT]  scratch folder $work (removed on exit), exported
#                          as GUI_TEST_WORK; GUI_TEST_MARKER=$work/marker;
#                          GUI_TEST_SCRIPTS=$here (a GUI script imports its
#                          siblings from there, e.g. las_tiles.py);
#                          $here is the folder of the test scripts. The
#                          screenshot's folder is made and an old one removed.
#   gui_run COMMAND...     starts Xvfb on a free display (-displayfd, so
#                          parallel tests never race for a number), runs
#                          COMMAND in the background (its output in
#                          $work/paraview.log, its pid in $gui_pid), calls
#                          gui_drive, then stops COMMAND and the display.
#                          When COMMAND could not connect to the display, all
#                          of it is retried on a fresh display (3 attempts):
#                          on a loaded machine a server has been seen to
#                          refuse a client that connected late.
#   gui_run_foreground COMMAND...
#                          the same retry for a command that needs a display
#                          but no driving (a pvpython rendering script); its
#                          output is printed and its exit status returned.
#   gui_wait_for FILE [SECONDS]
#                          waits until FILE is not empty; gives up early when
#                          ParaView has exited. The limit (GUI_TEST_WAIT,
#                          180 s unless given) is only there for hangs: no
#                          test asserts how long anything took.
#   gui_until SECONDS COMMAND...
#                          runs COMMAND every 0.2 s until it succeeds; fails
#                          when it still fails after SECONDS (a limit for
#                          hangs only) or once ParaView has exited. Steps
#                          wait for what they need (a file the GUI script
#                          writes, a dialog having the focus), never for a
#                          fixed time: a loaded machine only makes them later.
#   gui_mark_screen        captures the screen before a step that changes it.
#   gui_wait_still [SECONDS]
#                          waits until the screen has stopped changing (the
#                          GUI has drawn what it was asked to): three
#                          captures in a row that differ in at most a text
#                          cursor's pixels. After gui_mark_screen, first
#                          waits for the screen to differ from the mark: a
#                          GUI busy computing or laying out leaves the
#                          screen still too, before it draws.
#   gui_focused WINDOW     true when WINDOW has the keyboard focus.
#   gui_visible NAME       true when a window named NAME is showing.
#   expect LINE            passes when the variable $state holds LINE as a
#                          whole line, else prints FAILED and sets status=1.
#   gui_place_window [NAME]
#                          finds the visible window NAME ("ParaView") into
#                          $window, puts it at 0,0 in 1600x1000, and waits
#                          until it has been drawn there (gui_wait_still).
#   gui_capture FILE       the whole screen as a picture.
#   gui_type_in_dialog NAME KEYS TEXT
#                          focuses $window, presses KEYS (ctrl+o), waits for
#                          the dialog NAME to show and take the focus, types
#                          TEXT and Enter; fails when no dialog showed. The
#                          screen is marked before Enter (gui_wait_still).
#   gui_open_and_apply FILE PATTERN
#                          opens FILE through File > Open (Ctrl+O, the path
#                          typed, Enter), applies it (Alt+A), and waits until
#                          a line of $work/state (the test's GUI script
#                          writes it after each render) matches PATTERN and
#                          the screen is still; a dialog that did not show is
#                          noted in $work/events.
#   gui_quick_launch LABEL creates a filter on the active source by the quick
#                          launch: Ctrl+Space, LABEL typed into its dialog,
#                          Enter; returns once the dialog has closed. The
#                          screen is marked before Enter (gui_wait_still).
#   gui_wait_exit SECONDS  waits for ParaView to exit by itself; fails when
#                          it is still running.
#   gui_count_pixels IMAGE OPTIONS CONDITION...
#                          counts the pixels of IMAGE, as ImageMagick's
#                          OPTIONS (-crop 100x100+0+0 +repage) leave it,
#                          that meet each CONDITION: a numpy expression of
#                          the 0-255 arrays r, g, b ("(r > 200) & (g < 40)").
#                          Prints the counts, one a condition.
#   gui_require_screenshot FILE
#                          fails, saying so, when FILE (the screenshot) is
#                          missing or empty.
#   gui_report_events      prints each line of $work/events (the steps'
#                          findings, such as a dialog that did not show) as
#                          a failure, and then sets status=1.
#   gui_check_no_gdal_probe
#                          sets status=1 when ParaView's log shows GDAL's
#                          "not recognized as a supported file format"
#                          (its raster reader probing a point cloud file).
#   gui_read_words IMAGE OPTIONS PSM WORDS
#                          the distinct words of WORDS (an alternation,
#                          "Ridge|Valley") that tesseract (page segmentation
#                          PSM) reads in IMAGE as ImageMagick's OPTIONS
#                          (crop, enlarge) leave it, in gray: sorted, on one
#                          line. Fails, saying so, when tesseract is missing.
#   gui_read_marker PATTERN
#                          reads $GUI_TEST_MARKER into $marker, prints it,
#                          and fails unless it matches the glob PATTERN.
# On a failed exit, the last lines of ParaView's and Xvfb's logs are printed;
# ParaView's log is kept next to the screenshot (NAME.paraview.log).
# GUI_SCREEN sets the screen (1600x1000x24).
# Every test has its own HOME (in $work): ParaView's user settings and the
# state it saves on exit are the test's own, so tests can run side by side.

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
gui_pid="" gui_xvfb_pid="" gui_screenshot="" window=""

gui_init() {
  gui_screenshot=${1:-}
  work=$(mktemp -d)
  export GUI_TEST_WORK=$work GUI_TEST_MARKER=$work/marker GUI_TEST_SCRIPTS=$here
  # Caches (Mesa's compiled shaders, fonts) stay shared: they are built for
  # concurrent readers, and only save time.
  export XDG_CACHE_HOME=${XDG_CACHE_HOME:-${HOME:-/tmp}/.cache}
  export HOME=$work/home XDG_CONFIG_HOME=$work/home/.config
  mkdir -p "$XDG_CONFIG_HOME"
  if [ -n "$gui_screenshot" ]; then
    mkdir -p "$(dirname "$gui_screenshot")"
    rm -f "$gui_screenshot" "${gui_screenshot%.*}.paraview.log"
  fi
  trap gui_cleanup EXIT
  trap 'exit 143' TERM
  trap 'exit 130' INT
  trap 'exit 129' HUP
}

gui_cleanup() {
  local status=$?
  gui_stop_paraview
  gui_stop_display
  if [ "$status" -ne 0 ]; then
    if [ -s "$work/paraview.log" ]; then
      echo "--- last lines of the ParaView log:"
      tail -n 20 "$work/paraview.log"
    fi
    if [ -s "$work/xvfb.log" ]; then
      echo "--- last lines of the Xvfb log:"
      tail -n 5 "$work/xvfb.log"
    fi
  fi
  if [ -n "$gui_screenshot" ] && [ -s "$work/paraview.log" ]; then
    cp "$work/paraview.log" "${gui_screenshot%.*}.paraview.log" 2>/dev/null
  fi
  rm -rf "$work"
  exit "$status"
}

# Starts Xvfb on a display it chooses itself, and checks that a client can
# connect; a server that does not answer is replaced, up to three times.
# -noreset: by default Xvfb resets when its last client leaves, and refuses
# a client that connects during the reset (the check below is such a last
# client, and ParaView connects right after it).
gui_start_display() {
  local attempt i
  for attempt in 1 2 3; do
    rm -f "$work/display"
    Xvfb -displayfd 3 -screen 0 "${GUI_SCREEN:-1600x1000x24}" -nolisten tcp -noreset \
      3> "$work/display" 2>> "$work/xvfb.log" &
    gui_xvfb_pid=$!
    for i in $(seq 1 300); do
      [ -s "$work/display" ] && break
      kill -0 "$gui_xvfb_pid" 2>/dev/null || break
      sleep 0.1
    done
    if [ -s "$work/display" ]; then
      export DISPLAY=:$(head -n 1 "$work/display")
      if timeout 20 xdotool getdisplaygeometry > /dev/null 2>&1; then
        return 0
      fi
    fi
    echo "Xvfb did not answer (attempt $attempt), retrying" >&2
    gui_stop_display
    sleep 2
  done
  echo "FAILED: no X display after 3 attempts"
  return 1
}

gui_stop_display() {
  if [ -n "$gui_xvfb_pid" ]; then
    kill "$gui_xvfb_pid" 2>/dev/null
    wait "$gui_xvfb_pid" 2>/dev/null
    gui_xvfb_pid=""
  fi
}

gui_stop_paraview() {
  if [ -n "$gui_pid" ]; then
    kill "$gui_pid" 2>/dev/null
    wait "$gui_pid" 2>/dev/null
    gui_pid=""
  fi
}

gui_display_refused() {
  [ -n "$(gui_display_refused_line "$1")" ]
}

gui_display_refused_line() {
  grep -m 1 -E "bad X server connection|cannot connect to X server|could not connect to display" "$1" 2>/dev/null
}

# The default steps: wait for the script's marker, place the window, let it
# draw (the window placed, the screen stops changing), capture the screen.
gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER" && gui_place_window
  [ -n "$gui_screenshot" ] && gui_capture "$gui_screenshot"
  return 0
}

gui_run() {
  local attempt
  for attempt in 1 2 3; do
    gui_start_display || exit 1
    rm -f "$GUI_TEST_MARKER" "$GUI_TEST_MARKER".*
    "$@" > "$work/paraview.log" 2>&1 &
    gui_pid=$!
    gui_drive
    gui_stop_paraview
    gui_stop_display
    gui_display_refused "$work/paraview.log" || return 0
    echo "X connection failed (attempt $attempt: $(gui_display_refused_line "$work/paraview.log")), retrying" >&2
    sleep 2
  done
  echo "FAILED: X connection failed 3 times"
  exit 1
}

gui_run_foreground() {
  local attempt status
  for attempt in 1 2 3; do
    gui_start_display || return 1
    "$@" > "$work/command.log" 2>&1
    status=$?
    gui_stop_display
    if ! gui_display_refused "$work/command.log"; then
      cat "$work/command.log"
      return $status
    fi
    echo "X connection failed (attempt $attempt: $(gui_display_refused_line "$work/command.log")), retrying" >&2
    sleep 2
  done
  cat "$work/command.log"
  return 1
}

gui_wait_for() {
  gui_until "${2:-${GUI_TEST_WAIT:-180}}" test -s "$1"
}

gui_until() {
  local limit=$1 start=$SECONDS
  shift
  until "$@"; do
    if [ $((SECONDS - start)) -ge "$limit" ] || { [ -n "$gui_pid" ] && ! kill -0 "$gui_pid" 2>/dev/null; }; then
      "$@"
      return
    fi
    sleep 0.2
  done
}

gui_focused() {
  [ "$(xdotool getwindowfocus 2>/dev/null)" = "$1" ]
}

# Pixels that may differ between captures of a still screen: a blinking
# text cursor's.
gui_still_pixels=64

gui_mark_screen() {
  import -window root -depth 8 "rgb:$work/still_mark.rgb" 2>/dev/null
}

# shellcheck disable=SC2120 # callers pass a limit where they need one
gui_wait_still() {
  /usr/bin/python3 "$here/wait_still.py" "${1:-60}" "$gui_still_pixels" "$work/still_mark.rgb"
  rm -f "$work/still_mark.rgb"
}

# shellcheck disable=SC2120,SC2034 # tests name other windows; eval sets all
gui_place_window() {
  local WINDOW X Y WIDTH HEIGHT SCREEN
  window=$(timeout 60 xdotool search --sync --onlyvisible --name "${1:-ParaView}" 2>/dev/null | head -n 1)
  [ -n "$window" ] || return 1
  eval "$(xdotool getwindowgeometry --shell "$window")"
  [ "$X $Y $WIDTH $HEIGHT" = "0 0 1600 1000" ] && return 0
  gui_mark_screen
  xdotool windowmove "$window" 0 0 windowsize "$window" 1600 1000
  gui_wait_still
}

gui_capture() {
  import -window root "$1"
}

gui_open_and_apply() {
  gui_type_in_dialog "Open File" ctrl+o "$1" ||
    { echo "no Open File dialog for $1" >> "$work/events"; return; }
  gui_wait_still
  xdotool windowfocus --sync "$window"
  xdotool key --clearmodifiers alt+a
  gui_until 120 grep -q "$2" "$work/state"
  gui_wait_still
}

gui_type_in_dialog() {
  local dialog
  xdotool windowfocus --sync "$window"
  xdotool key --clearmodifiers "$2"
  dialog=$(timeout 60 xdotool search --sync --onlyvisible --name "$1" 2>/dev/null | head -n 1)
  [ -n "$dialog" ] || return 1
  gui_until 30 gui_focused "$dialog"
  xdotool type --delay 40 "$3"
  # The typed text drawn in the dialog: Enter then takes all of it.
  gui_wait_still
  gui_mark_screen
  xdotool key Return
}

gui_visible() {
  xdotool search --onlyvisible --name "$1" > /dev/null 2>&1
}

gui_focused_elsewhere() {
  local focus
  focus=$(xdotool getwindowfocus 2>/dev/null) && [ "$focus" != "$1" ]
}

gui_quick_launch() {
  local dialog
  xdotool windowfocus --sync "$window"
  xdotool key --clearmodifiers ctrl+space
  gui_until 30 gui_focused_elsewhere "$window"
  dialog=$(xdotool getwindowfocus 2>/dev/null)
  xdotool type --delay 80 "$1"
  # The list of matches drawn: Enter takes its first entry.
  gui_wait_still
  gui_mark_screen
  xdotool key Return
  gui_until 30 gui_focused_elsewhere "$dialog"
}

gui_wait_exit() {
  local i
  for i in $(seq 1 "$1"); do
    kill -0 "$gui_pid" 2>/dev/null || return 0
    sleep 1
  done
  ! kill -0 "$gui_pid" 2>/dev/null
}

gui_count_pixels() {
  local image=$1 options=$2
  shift 2
  # shellcheck disable=SC2086 # the options are words on purpose
  convert "$image" $options -depth 8 rgb:- | /usr/bin/python3 -c '
import sys
import numpy
r, g, b = numpy.frombuffer(sys.stdin.buffer.read(), numpy.uint8).reshape(-1, 3).astype(int).T
print(" ".join(str(numpy.count_nonzero(eval(condition))) for condition in sys.argv[1:]))' "$@"
}

gui_read_marker() {
  marker=$(cat "$GUI_TEST_MARKER" 2>/dev/null || echo "no marker: the GUI script did not run")
  echo "GUI script: $marker"
  # shellcheck disable=SC2254 # the pattern is a glob on purpose
  case "$marker" in $1) return 0 ;; esac
  return 1
}

expect() {
  if grep -qx "$1" <<< "$state"; then
    echo "as expected: $1"
  else
    echo "FAILED: expected '$1'"
    status=1
  fi
}

gui_require_screenshot() {
  [ -s "$1" ] && return 0
  echo "FAILED: no screenshot"
  return 1
}

gui_report_events() {
  [ -s "$work/events" ] || return 0
  sed "s/^/FAILED: /" "$work/events"
  status=1
}

gui_check_no_gdal_probe() {
  if grep -q "not recognized as a supported file format" "$work/paraview.log"; then
    echo "FAILED: GDAL's probe message on the terminal: $(grep -m 1 "not recognized" "$work/paraview.log")"
    status=1
  else
    echo "no GDAL probe message"
  fi
}

gui_read_words() {
  if ! command -v tesseract > /dev/null; then
    echo "FAILED: tesseract is not installed (Scripts/setup.sh installs it)" >&2
    return 1
  fi
  # shellcheck disable=SC2086 # the options are words on purpose
  convert "$1" $2 -colorspace Gray png:- | tesseract - - --psm "$3" 2>/dev/null |
    grep -o -w -E "$4" | sort -u | tr '\n' ' '
}
