#!/usr/bin/env bash
# Sets up, builds and runs the whole test suite: CTest (C++, pvpython, GUI
# under Xvfb, MPI, installed-tree example, accuracy regression), then the C++
# tests under AddressSanitizer + UndefinedBehaviorSanitizer, then a bounded
# fuzzing run of the numeric core.
set -euo pipefail
cd "$(dirname "$0")/.."
bash Scripts/setup.sh
(cd build && ctest --output-on-failure -j 2)
bash Scripts/sanitize.sh
bash Scripts/fuzz.sh "${PCURV_FUZZ_SECONDS:-60}"
