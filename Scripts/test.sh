#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: CTest (C++, pvpython, GUI
# under Xvfb, MPI, installed-tree example, accuracy regression), then the C++
# tests under AddressSanitizer + UndefinedBehaviorSanitizer, then a bounded
# fuzzing run of the numeric core. Prints each phase's time at the end.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
bash Scripts/setup.sh
set_up=$(date +%s)
(cd build && ctest --output-on-failure -j 2)
tested=$(date +%s)
bash Scripts/sanitize.sh
sanitized=$(date +%s)
bash Scripts/fuzz.sh "${PCURV_FUZZ_SECONDS:-60}"
echo "phases: setup $((set_up - start)) s, ctest $((tested - set_up)) s," \
  "sanitizers $((sanitized - tested)) s, fuzzing $(($(date +%s) - sanitized)) s"
