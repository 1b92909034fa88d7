#!/usr/bin/env bash
# ctest `sanitizers`: the library, opencv_test_event and the samples built with AddressSanitizer and
# UndefinedBehaviorSanitizer (gcc), then the unit tests (all but the long accuracy runs, below) and the samples
# run under them. Any memory error, leak or undefined
# behaviour aborts the run. Then the library and opencv_test_event built with ThreadSanitizer (build-tsan/),
# running StereoEventMatcher's row bands on several threads and the live cameras' threads on their fake USB:
# any data race aborts the run. The build dir is inside the clone (build-sanitizers/, ignored by git) and ccache
# runs with CCACHE_BASEDIR = the clone, so a fresh clone compiles from the cache.
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
  > "$build.configure.log" 2>&1 || { tail -40 "$build.configure.log"; exit 1; }
# Only what runs below: the other samples and the benchmark programs would compile for nothing.
cmake --build "$build" --target opencv_test_event event_stereo_overview event_evaluate event_info \
  > "$build.build.log" 2>&1 || { tail -60 "$build.build.log"; exit 1; }
echo "== sanitizers: opencv_test_event under ASan + UBSan"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions="$here/lsan.supp"
# Every unit test except the accuracy figures on long simulated runs (4-23 s each in Release, 6-16 times that
# here: the row alignment test took 35 s, the temporal prior's 69 s, the clock estimate's scenes 160-180 s).
# They run in the normal unit test job; under the sanitizers their code paths are taken by the shorter tests
# (the row bands' scenes, process() against processEvent(), the look-ahead and border closed forms, the filling
# on 400 ms of a pair, the clock estimate's one-line scene, the lifetime quality's closed forms) and by the
# realistic scene below.
skipped='StereoEventMatcher.coupled_beats_frame_sgbm_on_textured_scenes'
skipped+=':StereoEventMatcher.lifetime_modes_estimate_as_many_events_as_fixed_interval_from_the_start'
skipped+=':StereoEventMatcher.textured_scenes_meet_the_accuracy_and_density_targets'
skipped+=':StereoEventMatcher_Confidence.temporal_prior_raises_the_matching_rate_on_sparse_edges'
skipped+=':StereoEventMatcher_Confidence.rejection_is_the_threshold_and_the_confidence_ranks_the_estimates'
skipped+=':StereoEventMatcher_LookAhead.raises_the_matching_rate_on_low_contrast'
skipped+=':Event_RowAlignment.finds_the_simulated_row_offset_and_roll'
skipped+=':StereoEventMatcher.coupled_lifetimes_passed_on_without_limit_keep_the_start_up_ones'
skipped+=':StereoEventMatcher.coupled_lifetimes_are_refitted_after_a_copy_on_changing_speeds'
skipped+=':StereoEventMatcher.coupled_leads_frame_sgbm_by_ten_points_on_the_near_walker'
skipped+=':StereoEventMatcher_Confidence.an_uncertain_match_does_not_override_the_events_own_plane'
skipped+=':Event_ClockOffset.a_right_clock_moved_by_a_known_amount_moves_the_estimate_by_as_much'
skipped+=':Event_ClockOffset.a_walking_figure_tells_a_moved_clock_and_says_how_sure_it_is_of_its_own'
skipped+=':Event_ClockOffset.objects_that_each_move_at_one_speed_get_no_confident_wrong_offset'
skipped+=':StereoEventMatcher_Filling.puts_the_events_one_camera_misses_where_the_surface_around_them_is'
skipped+=':Event_LifetimeQuality.ranks_the_lifetimes_by_their_error_against_the_simulated_truth'
# The row bands against one thread: one of the six scene x mode cases (two_planes COUPLED, about 3 min of one
# core here). The bands' code is the same in every mode; every mode on one and two threads runs in
# lifetime_time_is_counted_only_when_on_and_changes_no_output (cluttered, 60 ms), the modes' own code in the
# single-thread tests, and cluttered COUPLED under TSan below.
for case in 1 2 3 4 5; do
  skipped+=":StereoEventMatcher_RowBands.give_the_results_of_one_thread_bit_for_bit/$case"
done
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
