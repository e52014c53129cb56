#!/usr/bin/env bash
# Builds the libFuzzer target on the numeric core (clang, with ASan and
# UBSan) and runs it for a bounded time over the corpus kept in
# Testing/Fuzz/corpus. Fails on any crash or broken invariant.
#   Scripts/fuzz.sh [seconds=60]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
if ! command -v clang++ > /dev/null || ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a > /dev/null 2>&1; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends clang libclang-rt-dev
fi
mkdir -p build-fuzz
clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I Filters -I /usr/include/eigen3 \
  Testing/Fuzz/FuzzCurvatureCore.cxx Filters/PrincipalCurvatureCore.cxx Filters/PointGrid.cxx \
  Filters/DynamicAdjustment.cxx -o build-fuzz/FuzzCurvatureCore
# New interesting inputs go to a scratch folder; the kept corpus is read only.
rm -rf build-fuzz/new-corpus
mkdir -p build-fuzz/new-corpus
./build-fuzz/FuzzCurvatureCore -max_total_time="$seconds" -max_len=4096 -timeout=10 \
  -print_final_stats=1 build-fuzz/new-corpus Testing/Fuzz/corpus
echo "fuzzing: no crash in ${seconds} s"
