# Sourced by sanitizers.sh and contrib_build.sh: unit tests that the standalone job (ctest opencv_test_event)
# runs and these two stages leave out, as gtest filter lists (':'-separated).
#
# long_accuracy_tests: accuracy figures on long simulated runs (5-65 s each in Release, 6-16 times that under
# the sanitizers). Their code paths are taken by shorter tests: the row bands' scenes, process() against
# processEvent(), the look-ahead and border closed forms, the filling on 400 ms of a pair, the clock estimate's
# one-line scene, the lifetime quality's closed forms, the averaging's output-only test, the cost row step's
# event-by-event test and the realistic scenes the samples run.
long_accuracy_tests='StereoEventMatcher.coupled_beats_frame_sgbm_on_textured_scenes'
long_accuracy_tests+=':StereoEventMatcher.lifetime_modes_estimate_as_many_events_as_fixed_interval_from_the_start'
long_accuracy_tests+=':StereoEventMatcher.textured_scenes_meet_the_accuracy_and_density_targets'
long_accuracy_tests+=':StereoEventMatcher_Confidence.temporal_prior_raises_the_matching_rate_on_sparse_edges'
long_accuracy_tests+=':StereoEventMatcher_Confidence.rejection_is_the_threshold_and_the_confidence_ranks_the_estimates'
long_accuracy_tests+=':StereoEventMatcher_LookAhead.raises_the_matching_rate_on_low_contrast'
long_accuracy_tests+=':Event_RowAlignment.finds_the_simulated_row_offset_and_roll'
long_accuracy_tests+=':StereoEventMatcher.coupled_lifetimes_passed_on_without_limit_keep_the_start_up_ones'
long_accuracy_tests+=':StereoEventMatcher.coupled_lifetimes_are_refitted_after_a_copy_on_changing_speeds'
long_accuracy_tests+=':StereoEventMatcher.coupled_leads_frame_sgbm_by_ten_points_on_the_near_walker'
long_accuracy_tests+=':StereoEventMatcher_Confidence.an_uncertain_match_does_not_override_the_events_own_plane'
long_accuracy_tests+=':Event_ClockOffset.a_right_clock_moved_by_a_known_amount_moves_the_estimate_by_as_much'
long_accuracy_tests+=':Event_ClockOffset.a_walking_figure_tells_its_clock_to_within_half_a_millisecond'
long_accuracy_tests+=':Event_ClockOffset.objects_that_each_move_at_one_speed_get_no_confident_wrong_offset'
long_accuracy_tests+=':StereoEventMatcher_Filling.puts_the_events_one_camera_misses_where_the_surface_around_them_is'
long_accuracy_tests+=':Event_LifetimeQuality.ranks_the_lifetimes_by_their_error_against_the_simulated_truth'
long_accuracy_tests+=':StereoEventMatcher_Averaging.brings_a_pairs_estimates_to_within_a_pixel_of_the_truth'
long_accuracy_tests+=':StereoEventMatcher.subpixel_disparities_are_not_pulled_towards_whole_pixels'
long_accuracy_tests+=':StereoEventMatcher_CostRowStep.every_other_row_matches_as_well_as_every_row'

# row_band_cases: the row bands against one thread, scene x mode case N (0-5; 3 is cluttered COUPLED, the one
# that takes every path of the bands). The bands' code is the same in every mode; every mode on one and two
# threads also runs in StereoEventMatcher.lifetime_time_is_counted_only_when_on_and_changes_no_output.
row_band_cases()
{
  local list='' n
  for n in "$@"; do list+="${list:+:}StereoEventMatcher_RowBands.give_the_results_of_one_thread_bit_for_bit/$n"; done
  echo "$list"
}
