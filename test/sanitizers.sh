#!/usr/bin/env bash
# ctest `sanitizers`: the library, opencv_test_event and the samples built with AddressSanitizer and
# UndefinedBehaviorSanitizer (gcc), then the unit tests (all but the long accuracy runs: long_tests.sh) and the
# samples run under them. Any memory error, leak or undefined behaviour aborts the run. Then the library and
# opencv_test_event built with ThreadSanitizer (build-tsan/), running StereoEventMatcher's row bands on several
# threads and the live cameras' threads on their fake USB: any data race aborts the run. The build dir is inside
# the clone (build-sanitizers/, ignored by git) and ccache runs with CCACHE_BASEDIR = the clone, so a fresh clone
# compiles from the cache.
#
#   test/sanitizers.sh <opencv-source-dir> [build-dir]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
src=${1:?usage: sanitizers.sh <opencv-source-dir> [build-dir]}
cache=${OPENCV_EVENT_CACHE:-/var/cache/opencv_event}
build=${2:-$repo/build-sanitizers}
export CCACHE_DIR=${CCACHE_DIR:-$cache/ccache}
export CCACHE_BASEDIR=$repo
export CCACHE_NOHASHDIR=1  # -g would otherwise hash the build path into every object
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
generator=()
command -v ninja >/dev/null && generator=(-G Ninja)
echo "== sanitizers: building in $build"
cmake -S "$repo" -B "$build" "${generator[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DOPENCV_EVENT_OPENCV_SOURCE_DIR="$src" -DOPENCV_EVENT_BUILD_CONTRIB_TEST=OFF -DOPENCV_EVENT_BUILD_PERF_TESTS=OFF -DOPENCV_EVENT_BUILD_PYTHON=OFF \
  -DOPENCV_EVENT_TEST_COMPILE_OPTIONS=-O0 \
  > "$build.configure.log" 2>&1 || { tail -40 "$build.configure.log"; exit 1; }
# Only what runs below: the other samples and the benchmark programs would compile for nothing.
cmake --build "$build" --target opencv_test_event event_stereo_overview event_evaluate event_info \
  > "$build.build.log" 2>&1 || { tail -60 "$build.build.log"; exit 1; }
echo "== sanitizers: opencv_test_event under ASan + UBSan"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions="$here/lsan.supp"
# Every unit test except the accuracy figures on long simulated runs (long_tests.sh) and the row bands against
# one thread (all six scene x mode cases: cluttered COUPLED runs under TSan below).
source "$here/long_tests.sh"
skipped="$long_accuracy_tests:$(row_band_cases 0 1 2 3 4 5)"
bash "$here/gtest_shards.sh" "$build/modules/event/opencv_test_event" --gtest_filter="-$skipped"
echo "== sanitizers: samples on the simulator and on every real recording"
work=$(mktemp -d)
"$build/samples/event_stereo_overview" --scene=cluttered --simulate-ms=150 --output="$work/overview" > /dev/null
"$build/samples/event_evaluate" --scene=two_planes --method=lifetime --duration-ms=100 --output="$work/eval" > /dev/null
"$build/samples/event_evaluate" --scene=two_planes --method=sgbm --duration-ms=100 --output="$work/eval2" > /dev/null
"$build/samples/event_evaluate" --scene=boxes --method=coupled --duration-ms=300 --output="$work/eval3" > /dev/null
shared="${OPENCV_EVENT_SHARED_DATA:-$repo/../shared/data}"
if [ -d "$shared" ]; then
  # Every recording read in full. A file the readers refuse (a format or message name they do not read yet)
  # is a cv::Exception that event_info reports, naming the file, with exit status 1; a sanitizer's finding
  # aborts (UBSan told to as well), so any other status fails the stage.
  status=0
  UBSAN_OPTIONS=$UBSAN_OPTIONS:abort_on_error=1 "$build/samples/event_info" "$shared"/format_samples/* \
    "$shared"/stereo_dvs128_tum/* > "$work/info.txt" || status=$?
  [ "$status" -le 1 ] || { echo "== sanitizers: event_info on the recordings ended with status $status"; exit 1; }
  echo "== sanitizers: $(grep -c "format:" "$work/info.txt") recordings read; refused with a message:"
  grep "  error:" "$work/info.txt" || echo "  none"
  [ "$status" = 0 ] || grep -q "  error:" "$work/info.txt" \
    || { echo "== sanitizers: event_info failed without naming a refused file"; exit 1; }
else
  echo "== sanitizers: SKIP the real recordings: $shared not found"
fi
rm -rf "$work"

tsan=${build%-sanitizers}-tsan
[ "$tsan" != "$build" ] || tsan=$build-tsan
echo "== sanitizers: building opencv_test_event with ThreadSanitizer in $tsan"
tflags="-fsanitize=thread -fno-omit-frame-pointer -g -O1"
cmake -S "$repo" -B "$tsan" "${generator[@]}" "${launcher[@]}" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="$tflags" -DCMAKE_C_FLAGS="$tflags" -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" \
  -DOPENCV_EVENT_OPENCV_SOURCE_DIR="$src" -DOPENCV_EVENT_BUILD_CONTRIB_TEST=OFF -DOPENCV_EVENT_BUILD_PERF_TESTS=OFF -DOPENCV_EVENT_BUILD_PYTHON=OFF \
  -DOPENCV_EVENT_TEST_FILES="test_main.cpp;test_stereo_row_bands.cpp;test_event_capture_davis.cpp;test_usb_link_device.cpp" \
  > "$tsan.configure.log" 2>&1 || { tail -40 "$tsan.configure.log"; exit 1; }
cmake --build "$tsan" --target opencv_test_event > "$tsan.build.log" 2>&1 || { tail -60 "$tsan.build.log"; exit 1; }
echo "== sanitizers: StereoEventMatcher's row bands and the live cameras' threads under TSan"
# Three of the eight row-band tests (a calibration that moves rows, on 4 threads; a packet cut short by a bad
# event; cluttered COUPLED on 2, 3 and 7 threads): under TSan each runs 20-40 times slower, and these three
# take every path of the bands (waits both ways, expiries, outside events, a failing packet). The live path on
# its fakes: USB callbacks on a control request's thread while the reader thread reads, the reader threads of
# a stereo pair, their clock arming and shutdown (a few seconds). Two shards: cluttered COUPLED, the longest,
# alone on one and the rest on the other (gtest's round robin put it beside the next longest).
GTEST_SHARD_FILTERS='StereoEventMatcher_RowBands.give_the_results_of_one_thread_bit_for_bit/3;StereoEventMatcher.row_bands_*:Event_UsbLinkDevice.*:Event_Capture_Davis.*' \
  TSAN_OPTIONS=halt_on_error=1 bash "$here/gtest_shards.sh" "$tsan/modules/event/opencv_test_event"
echo "== sanitizers: clean"
