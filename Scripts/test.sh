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
# The sanitizers' build, then the fuzz targets' build, run beside CTest
# at the lowest priority: they take only the CPU that CTest leaves idle (a
# core while a GUI test waits for ParaView to draw), so CTest runs as fast
# as alone. Their logs are printed only on a failure.
mkdir -p build
rm -f build/sanitize-build.ended
setsid nice -n 19 bash -c "bash Scripts/sanitize.sh --build-only; status=\$?
  touch build/sanitize-build.ended; exit \$status" > build/sanitize-build.log 2>&1 &
sanitize_build=$!
setsid nice -n 19 bash -c "until [ -e build/sanitize-build.ended ]; do sleep 2; done
  exec bash Scripts/fuzz.sh --build-only" > build/fuzz-build.log 2>&1 &
fuzz_build=$!
trap 'kill -- -"$sanitize_build" -"$fuzz_build" 2>/dev/null || true' EXIT
ctest_status=0
(cd build && ctest --output-on-failure -j 2) || ctest_status=$?
tested=$(date +%s)
if ! wait "$sanitize_build"; then
  cat build/sanitize-build.log
  echo "the sanitizers' build failed"
  exit 1
fi
[ "$ctest_status" -eq 0 ] || exit "$ctest_status"
sanitize_built=$(date +%s)
tail -n 1 build/sanitize-build.log
bash Scripts/sanitize.sh --test-only
sanitized=$(date +%s)
if ! wait "$fuzz_build"; then
  cat build/fuzz-build.log
  echo "the fuzz targets' build failed"
  exit 1
fi
trap - EXIT
fuzz_built=$(date +%s)
tail -n 1 build/fuzz-build.log
bash Scripts/fuzz.sh --fuzz-only "${PCURV_FUZZ_SECONDS:-60}"
echo "phases: setup $((set_up - start)) s, ctest $((tested - set_up)) s" \
  "(the sanitizers' build beside it, then $((sanitize_built - tested)) s more)," \
  "sanitizer tests $((sanitized - sanitize_built)) s, fuzzing $(($(date +%s) - sanitized)) s" \
  "(its build's rest $((fuzz_built - sanitized)) s)"
