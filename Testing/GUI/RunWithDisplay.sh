#!/usr/bin/env bash
# Runs a command under a private Xvfb display (GuiHarness.sh), retried on a
# fresh display when the X connection fails.
#   RunWithDisplay.sh COMMAND [ARGUMENTS...]
set -u
source "$(dirname "$0")/GuiHarness.sh"
gui_init
GUI_SCREEN=1280x1024x24 gui_run_foreground "$@"
