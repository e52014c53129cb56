#!/usr/bin/env bash
# Runs a command under a fresh Xvfb display (xvfb-run), retrying up to three
# times when the X connection fails: on loaded CI machines Xvfb has been
# seen to refuse a client that connects many seconds after it started.
#   RunWithDisplay.sh COMMAND [ARGUMENTS...]
set -u
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for attempt in 1 2 3; do
  xvfb-run -a -n $((150 + attempt * 7)) -s "-screen 0 1280x1024x24" "$@" > "$log" 2>&1
  status=$?
  if ! grep -q "bad X server connection" "$log"; then
    cat "$log"
    exit $status
  fi
  echo "X connection failed (attempt $attempt), retrying" >&2
  sleep 2
done
cat "$log"
exit 1
