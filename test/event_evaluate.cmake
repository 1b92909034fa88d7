# ctest `event_evaluate_consistency`: the evaluation tool gives the same metrics on a simulated scene whether
# the ground truth comes from the simulator in memory or from a written recording and its .gt.csv side file
# (which proves the side file lines up with the events), and writes its report and pictures.
foreach(v EVALUATE OVERVIEW LIFETIME WORK_DIR)
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

# A scene simulated on another sensor model (--sensor): event_lifetime writes 1 s of the fan on a DVS128 with
# its ground truth; evaluated from that file and simulated in memory, the lifetimes' metrics agree.
run_step("${LIFETIME}" --scene=fan --sensor=DVS128 --every-ms=1000 "--output=${WORK_DIR}/dvs128_recording")
run_step("${EVALUATE}" --scene=fan --sensor=DVS128 --duration-ms=1000 --method=lifetime "--output=${WORK_DIR}/dvs128_memory")
run_step("${EVALUATE}" "--input=${WORK_DIR}/dvs128_recording/fan.aedat4" --method=lifetime "--output=${WORK_DIR}/dvs128_file")
expect_same_metrics(dvs128_memory dvs128_file " on a DVS128")
# Without --sensor the scene is simulated on a DAVIS240: other events, other metrics.
run_step("${EVALUATE}" --scene=fan --duration-ms=1000 --method=lifetime "--output=${WORK_DIR}/davis240_memory")
file(STRINGS "${WORK_DIR}/davis240_memory/metrics.csv" davis240 REGEX "^events,")
file(STRINGS "${WORK_DIR}/dvs128_memory/metrics.csv" dvs128 REGEX "^events,")
if(davis240 STREQUAL dvs128)
  message(FATAL_ERROR "--sensor=DVS128 simulated the same events as the DAVIS240 default: ${dvs128}")
endif()
