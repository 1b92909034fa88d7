# ctest `event_evaluate_consistency`: the evaluation tool gives the same metrics on a simulated scene whether
# the ground truth comes from the simulator in memory or from a written recording and its .gt.csv side file
# (which proves the side file lines up with the events), and writes its report and pictures.
foreach(v EVALUATE OVERVIEW WORK_DIR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "event_evaluate.cmake: ${v} not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
include("${CMAKE_CURRENT_LIST_DIR}/run_step.cmake")

# The metrics of the runs in ${WORK_DIR}/<memory> and ${WORK_DIR}/<file>, timings aside, must be equal; the
# memory run's metrics are left in `metrics` for further checks.
function(expect_same_metrics memory file what)
  file(STRINGS "${WORK_DIR}/${memory}/metrics.csv" a REGEX "^[a-z_0-9]+,")
  file(STRINGS "${WORK_DIR}/${file}/metrics.csv" b REGEX "^[a-z_0-9]+,")
  list(FILTER a EXCLUDE REGEX "^(time_per_event|filter_mev_per_s)")
  list(FILTER b EXCLUDE REGEX "^(time_per_event|filter_mev_per_s)")
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "metrics${what} differ:\nmemory: ${a}\nfile:   ${b}")
  endif()
  set(metrics "${a}" PARENT_SCOPE)
endfunction()

run_step("${EVALUATE}" --scene=two_planes --duration-ms=200 "--output=${WORK_DIR}/memory")
run_step("${OVERVIEW}" --scene=two_planes --simulate-ms=200 "--output=${WORK_DIR}/recording")
run_step("${EVALUATE}" "--input=${WORK_DIR}/recording/two_planes.aedat4" "--output=${WORK_DIR}/file")
expect_same_metrics(memory file "")
list(FIND metrics "events,0" empty)
if(NOT empty EQUAL -1)
  message(FATAL_ERROR "no events were evaluated")
endif()
foreach(f report.md disparity_error_histogram.png disparity_vs_truth.png)
  if(NOT EXISTS "${WORK_DIR}/file/${f}")
    message(FATAL_ERROR "${f} was not written")
  endif()
endforeach()

# With a noise filter in front, the same again: the filter sees the same events from memory and from the file.
run_step("${EVALUATE}" --scene=two_planes --duration-ms=200 --filter=background_activity "--output=${WORK_DIR}/memory_filter")
run_step("${EVALUATE}" "--input=${WORK_DIR}/recording/two_planes.aedat4" --filter=background_activity "--output=${WORK_DIR}/file_filter")
expect_same_metrics(memory_filter file_filter " with a filter")
list(FIND metrics "filter,background_activity" named)
if(named EQUAL -1)
  message(FATAL_ERROR "the filter's figures are missing from metrics.csv: ${metrics}")
endif()
if(NOT EXISTS "${WORK_DIR}/file_filter/filter_before_after.png")
  message(FATAL_ERROR "filter_before_after.png was not written")
endif()
