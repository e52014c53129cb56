#!/usr/bin/env bash
# Builds the libFuzzer targets on the numeric core (Testing/Fuzz, clang with
# ASan and UBSan) in build-fuzz/, then
#  1. replays every input in Testing/Fuzz/regressions (inputs that once
#     crashed, hung or broke an invariant: each must now pass), and
#  2. fuzzes for a bounded time from the corpus kept in Testing/Fuzz/corpus
#     (read only: new inputs go to build-fuzz/new-corpus, crashes to
#     build-fuzz/crash-*, hangs of more than 10 s to build-fuzz/timeout-*).
#  3. fuzzes the file parsers (text clouds, OFF) for a quarter of the time.
# Fails when any step finds a crash, a hang, undefined behavior or a
# broken invariant.
#   Scripts/fuzz.sh [seconds=60]
#   Scripts/fuzz.sh --build-only          # or --fuzz-only [seconds]: one step
# PCURV_FUZZ_SKIP_KNOWN_BUGS=1 keeps the fuzzer away from overflowing grid
# coordinates (where the fixed PointGrid bugs of the target's source were).
set -euo pipefail
cd "$(dirname "$0")/.."
step=all
case "${1:-}" in --build-only | --fuzz-only) step=$1; shift ;; esac
seconds=${1:-60}
if ! command -v clang++ > /dev/null ||
  ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a > /dev/null 2>&1; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  # The package lists may be missing or stale on a fresh machine.
  DEBIAN_FRONTEND=noninteractive $sudo apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends clang libclang-rt-dev
fi
start=$(date +%s)
if [ "$step" != --fuzz-only ]; then
  # The core library and the fuzz target alone (no ParaView), built by clang
  # with the sanitizers; the fuzzer's own instrumentation on every core file.
  flags="-O1 -g -fsanitize=fuzzer-no-link,address,undefined,float-cast-overflow -fno-sanitize-recover=all"
  nice cmake -S . -B build-fuzz -DPCURV_CORE_ONLY=ON -DCMAKE_BUILD_TYPE=None \
    -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DPCURV_FUZZ_SKIP_KNOWN_BUGS="${PCURV_FUZZ_SKIP_KNOWN_BUGS:-0}" > /dev/null
  nice cmake --build build-fuzz -j 2 --target FuzzCurvatureCore FuzzFileParsing
  cp build-fuzz/Testing/Fuzz/FuzzCurvatureCore build-fuzz/FuzzCurvatureCore
  cp build-fuzz/Testing/Fuzz/FuzzFileParsing build-fuzz/FuzzFileParsing
fi
built=$(date +%s)
if [ "$step" = --build-only ]; then
  echo "fuzz: build $((built - start)) s"
  exit 0
fi
export ASAN_OPTIONS="abort_on_error=1:halt_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
failed=0

# 1. Known reproducers, one process each so that one hang does not hide the
#    others.
for input in Testing/Fuzz/regressions/*; do
  [ -f "$input" ] || continue
  if timeout 120 ./build-fuzz/FuzzCurvatureCore -timeout=10 "$input" > build-fuzz/regression.log 2>&1; then
    echo "regression $(basename "$input"): passes"
  else
    echo "regression $(basename "$input"): FAILS"
    grep -E "runtime error|invariant broken|ALARM|ERROR" build-fuzz/regression.log | head -3 | sed 's/^/    /'
    failed=1
  fi
done

# 2. Fuzzing.
rm -rf build-fuzz/new-corpus
mkdir -p build-fuzz/new-corpus
if ! nice ./build-fuzz/FuzzCurvatureCore -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -rss_limit_mb=2048 -artifact_prefix=build-fuzz/ -print_final_stats=1 \
  build-fuzz/new-corpus Testing/Fuzz/corpus > build-fuzz/fuzz.log 2>&1; then
  grep -E "runtime error|invariant broken|ALARM|ERROR|Test unit written" build-fuzz/fuzz.log | head -5 || true
  echo "fuzzing: FAILED (log in build-fuzz/fuzz.log; reproduce with build-fuzz/FuzzCurvatureCore <artifact>)"
  failed=1
else
  grep -E "^#[0-9]+ +DONE|stat::number_of_executed_units" build-fuzz/fuzz.log || true
  echo "fuzzing: no crash, hang or broken invariant in ${seconds} s"
fi
# 3. The file parsers behind the readers (text clouds, OFF meshes), a
#    quarter of the time, from no corpus (their inputs are short text).
#    After the core's fuzzing, not beside it: on a busy machine the two
#    would share a core and each would try fewer inputs in its time.
parse_seconds=$(( seconds / 4 > 15 ? seconds / 4 : 15 ))
mkdir -p build-fuzz/parse-corpus
if ! nice ./build-fuzz/FuzzFileParsing -max_total_time="$parse_seconds" -max_len=2048 -timeout=10 \
  -rss_limit_mb=1024 -artifact_prefix=build-fuzz/parse- build-fuzz/parse-corpus > build-fuzz/parse.log 2>&1; then
  grep -E "runtime error|invariant broken|ALARM|ERROR|Test unit written" build-fuzz/parse.log | head -5 || true
  echo "fuzzing the file parsers: FAILED (log in build-fuzz/parse.log)"
  failed=1
else
  echo "fuzzing the file parsers: no crash, hang or broken invariant in ${parse_seconds} s"
fi
echo "fuzz: build $((built - start)) s, regressions and fuzzing $(($(date +%s) - built)) s"
exit $failed
