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
#     sleep 5
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
#   gui_place_window [NAME]
#                          finds the visible window NAME ("ParaView") into
#                          $window and puts it at 0,0 in 1600x1000.
#   gui_capture FILE       the whole screen as a picture.
#   gui_type_in_dialog NAME KEYS TEXT
#                          focuses $window, presses KEYS (ctrl+o), waits for
#                          the dialog NAME, types TEXT and Enter; fails
#                          when no dialog showed.
#   gui_wait_exit SECONDS  waits for ParaView to exit by itself; fails when
#                          it is still running.
#   gui_read_marker PATTERN
#                          reads $GUI_TEST_MARKER into $marker, prints it,
#                          and fails unless it matches the glob PATTERN.
# On a failed exit, the last lines of ParaView's and Xvfb's logs are printed;
# ParaView's log is kept next to the screenshot (NAME.paraview.log).
# GUI_SCREEN sets the screen (1600x1000x24).

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
gui_pid="" gui_xvfb_pid="" gui_screenshot="" window=""

gui_init() {
  gui_screenshot=${1:-}
  work=$(mktemp -d)
  export GUI_TEST_WORK=$work GUI_TEST_MARKER=$work/marker
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
# draw, capture the screen.
gui_drive() {
  gui_wait_for "$GUI_TEST_MARKER" && gui_place_window
  sleep 5
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
  local file=$1 limit=${2:-${GUI_TEST_WAIT:-180}} i
  for i in $(seq 1 "$limit"); do
    [ -s "$file" ] && return 0
    [ -n "$gui_pid" ] && ! kill -0 "$gui_pid" 2>/dev/null && break
    sleep 1
  done
  [ -s "$file" ]
}

gui_place_window() {
  window=$(timeout 60 xdotool search --sync --onlyvisible --name "${1:-ParaView}" 2>/dev/null | head -n 1)
  [ -n "$window" ] || return 1
  xdotool windowmove "$window" 0 0 windowsize "$window" 1600 1000
}

gui_capture() {
  import -window root "$1"
}

gui_type_in_dialog() {
  xdotool windowfocus --sync "$window"
  xdotool key --clearmodifiers "$2"
  timeout 60 xdotool search --sync --onlyvisible --name "$1" > /dev/null 2>&1 || return 1
  sleep 2
  xdotool type --delay 40 "$3"
  sleep 1
  xdotool key Return
}

gui_wait_exit() {
  local i
  for i in $(seq 1 "$1"); do
    kill -0 "$gui_pid" 2>/dev/null || return 0
    sleep 1
  done
  ! kill -0 "$gui_pid" 2>/dev/null
}

gui_read_marker() {
  marker=$(cat "$GUI_TEST_MARKER" 2>/dev/null || echo "no marker: the GUI script did not run")
  echo "GUI script: $marker"
  # shellcheck disable=SC2254 # the pattern is a glob on purpose
  case "$marker" in $1) return 0 ;; esac
  return 1
}
