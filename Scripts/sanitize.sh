#!/usr/bin/env bash
# The C++ tests built with AddressSanitizer and UndefinedBehaviorSanitizer,
# in build-asan/. Any sanitizer report fails the run.
#   Scripts/sanitize.sh            # build, then run the C++ tests
#   Scripts/sanitize.sh --build-only   # or --test-only: one step
#   PCURV_SANITIZE_TESTS='^BadInput' Scripts/sanitize.sh   # a subset
#
# Only our code is instrumented: ParaView's libraries are Debian's. Not run
# here: the pvpython, GUI and MPI tests (pvpython, pvbatch and paraview do
# not load the ASan runtime, which must come first in the process).
#
# Which C++ tests, and why: the sanitizers find memory errors and undefined
# behavior on the code a test executes, so the set is chosen to execute all
# the code the C++ tests reach, each path once, and every test of unusual
# values:
# - every bad-input, extreme-value, reader, writer and fuzz-seed test (the
#   values that break code are theirs);
# - one registration of each filter test, the default one (the widest
#   kernel), and CurvatureCoreGenericKernel for the portable kernels: the
#   <name>_STDThread twins run the same lines of our code on the portable
#   kernels (the filter runs its loops on STDThread in both);
# - of the accuracy tests, those with the smaller clouds: the ones left
#   out (HEAVY_REPEATS below) run paths the others already run, on larger
#   or noisier clouds of ordinary values.
# "The same code" was measured with a --coverage build: the set below
# executes every line and every function (each kernel's own) of Core/,
# FileFormats/, IO/ and Filters/ that it executes with the tests left
# out added back. Measure again before leaving out another test.
#
# Options, and why:
# - float-cast-overflow: GCC's -fsanitize=undefined leaves it out, and a
#   NaN or huge double cast to an integer (a grid cell index) is exactly the
#   undefined behavior bad input can cause.
# - detect_leaks=0: VTK keeps singletons (object factories, the SMP
#   backend, output windows) alive until exit by design; LeakSanitizer
#   reports them from ParaView's uninstrumented libraries.
# - alloc_dealloc_mismatch and ODR checks stay on: no false positive was
#   seen with ParaView 5.11 from Debian 12 (if one appears, suppress it for
#   the one library with a suppressions file, not globally).
# - -g1: line tables only, all the reports' stack traces need (file and
#   line of every frame); the full debug information of -g makes the build
#   slower and adds nothing to what the sanitizers find.
set -euo pipefail
cd "$(dirname "$0")/.."
step=${1:-all}
case "$step" in all | --build-only | --test-only) ;;
  *) echo "usage: Scripts/sanitize.sh [--build-only | --test-only]" >&2; exit 2 ;; esac
flags="-fsanitize=address,undefined,float-cast-overflow -fno-omit-frame-pointer -fno-sanitize-recover=all"
start=$(date +%s)
if [ "$step" != --test-only ]; then
  nice cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
    -DPCURV_BUILD_BENCHMARKS=OFF -DPCURV_BUILD_STUDY=OFF > /dev/null
  nice cmake --build build-asan -j 2 --target TestCurvatureCore TestPrincipalCurvatureEstimation \
    TestCloudEstimation TestOrientedCircles TestAutomaticScale TestNormalField TestNormalEstimation TestNeighborGrid TestOutliers TestOpenScans \
    TestDynamicAdjustment TestBadInputConfiguration TestBadInputPoints TestBadInputScale \
    TestLASReader TestLASWriter TestPointCloudWriters TestPLYReader ReplayReaderSeeds \
    TestCurvatureLines TestShapeClass TestTimeLeft
fi
built=$(date +%s)
if [ "$step" = --build-only ]; then
  echo "sanitizers: build $((built - start)) s"
  exit 0
fi
export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1:halt_on_error=1:detect_stack_use_after_return=1:strict_init_order=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd build-asan
# A test that reports anything aborts and fails; the timeout covers the
# slowdown of the sanitizers on a busy 2-core machine. Two tests at a time:
# most are single-threaded, and the sanitized runs are most of CI's time.
default_tests='^((CurvatureCoreGenericKernel|PrincipalCurvatureEstimation|DynamicAdjustment|BadInput(Configuration|Points|Scale))|(CurvatureCore|CloudEstimation|OrientedCircles|AutomaticScale|NormalField|NormalEstimation|NeighborGrid|Outliers|OpenScans)\..*|BadInputExtreme_.*|LASReader|LASWriter\..*|PointCloudWriters\..*|PLYReader|FuzzReaderSeeds|CurvatureLines\.(ExactEllipsoid|InputAndThreads)|ShapeClass\.(ClassRule|TrustedKeepsCrests)|TimeLeft\..*)$'
HEAVY_REPEATS='^(AutomaticScale\.(SharedFits|RoundedPositions|HeightJets|NoisyScan|AutomaticScale|WideLadder)|OrientedCircles\.(GatedThirdOrder|FourthOrder|FittedDirections)|NormalEstimation\.(NoisyGivenNormals|HeavyNoiseNormals)|Outliers\.NoFalseOutliers)$'
if [ -n "${PCURV_SANITIZE_TESTS:-}" ]; then
  selection=(-R "$PCURV_SANITIZE_TESTS")
else
  selection=(-R "$default_tests" -E "$HEAVY_REPEATS")
fi
nice ctest --output-on-failure --timeout 3600 -j 2 "${selection[@]}"
echo "sanitizers: build $((built - start)) s, tests $(($(date +%s) - built)) s"
