#!/usr/bin/env bash
# The C++ tests built with AddressSanitizer and UndefinedBehaviorSanitizer,
# in build-asan/. Any report fails the run. (ParaView's libraries are not
# instrumented; the pvpython, GUI and MPI tests are not run here.)
set -euo pipefail
cd "$(dirname "$0")/.."
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" -DPCURV_BUILD_BENCHMARKS=OFF > /dev/null
cmake --build build-asan -j "$(nproc)" --target TestCurvatureCore TestPrincipalCurvatureEstimation \
  TestDynamicAdjustment TestBadInput
# detect_leaks=0: VTK's singletons are not freed at exit by design.
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:halt_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd build-asan
ctest --output-on-failure -R "^(CurvatureCore|PrincipalCurvatureEstimation|PrincipalCurvatureEstimation_STDThread|DynamicAdjustment|BadInput|BadInput_STDThread)$"
