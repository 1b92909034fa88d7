# ctest `event_info_cli`: event_info on a fixture whose facts are known by construction, on a missing file
# (exit status 1, the error names the file), on a file cut off mid-line (what came before, then the error) and on
# command-line mistakes (exit status 2).
file(MAKE_DIRECTORY "${WORK_DIR}")
set(fixture "${WORK_DIR}/three_events.txt")
file(WRITE "${fixture}" "# fixture\n8 6\n0.001 1 2 1 0\n0.002 3 4 0 1\n0.005 7 5 1 1\n0.006 9 9 1 0\n")
execute_process(COMMAND "${EVENT_INFO}" --json "${fixture}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "event_info failed on the fixture (${rc})")
endif()
# 4 lines, one outside the 8 x 6 sensor (9, 9); ON 2 of the 3 delivered; cameras: left 1, right 2.
foreach(expected [["format": "TEXT"]] [["width": 8]] [["height": 6]] [["stereo": true]] [["events": 3]]
                 [["on": 2]] [["left": 1]] [["right": 2]] [["first_us": 1000]] [["last_us": 5000]]
                 [["rejected_outside": 1]] [["x_min": 1, "x_max": 7, "y_min": 2, "y_max": 5]])
  string(FIND "${out}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "event_info --json output lacks ${expected}")
  endif()
endforeach()
# --stats, per camera: the right camera's two events, (3, 4) OFF and (7, 5) ON, are one of each polarity and
# not neighbours (both isolated); the left camera's one event is ON.
execute_process(COMMAND "${EVENT_INFO}" --json --stats "${fixture}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
foreach(expected [["camera": 0, "event_rate": 0, "on_share": 1,]] [["camera": 1, "event_rate": 666.667, "on_share": 0.5,]]
                 [["isolated_share": 1, "active_pixel_share": 0.0416667}]])
  string(FIND "${out}" "${expected}" at)
  if(NOT rc EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "event_info --json --stats output lacks ${expected}: ${out}")
  endif()
endforeach()
# A file without the sensor size: the text says so, and --stats, which needs it, names the smallest sensor
# that holds the events ((3, 4) and (7, 5): 8 x 6) instead of failing on the file.
set(no_size "${WORK_DIR}/no_size.txt")
file(WRITE "${no_size}" "0.001 3 4 0 1\n0.002 7 5 1 1\n")
execute_process(COMMAND "${EVENT_INFO}" --stats "${no_size}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "sensor: +not recorded in this file"
   OR NOT out MATCHES "pixels: +x 3..7, y 4..5" OR NOT out MATCHES "give --sensor=WxH \\(at least 8 x 6 for these events\\)")
  message(FATAL_ERROR "event_info --stats on a file without a sensor size: exit status ${rc} and: ${out}")
endif()
# A file that counts pixels from 1 on an 8 x 6 sensor: its last column (8) lies outside, no event lies in
# column or row 0, and the text says to give --one-based; given it, nothing is outside.
set(one_based "${WORK_DIR}/one_based.txt")
file(WRITE "${one_based}" "8 6\n0.001 1 2 1\n0.002 8 6 0\n")
execute_process(COMMAND "${EVENT_INFO}" "${one_based}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "rejected: +1 outside the sensor" OR NOT out MATCHES "give --one-based")
  message(FATAL_ERROR "event_info on a file counted from 1: exit status ${rc} and: ${out}")
endif()
execute_process(COMMAND "${EVENT_INFO}" --one-based "${one_based}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0 OR NOT out MATCHES "rejected: +0 outside the sensor" OR NOT out MATCHES "pixels: +x 0..7, y 1..5")
  message(FATAL_ERROR "event_info --one-based on a file counted from 1: exit status ${rc} and: ${out}")
endif()
execute_process(COMMAND "${EVENT_INFO}" "${WORK_DIR}/missing.aedat4" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 1 OR NOT out MATCHES "missing.aedat4: cannot open")
  message(FATAL_ERROR "a missing file gave exit status ${rc} and: ${out}")
endif()
# Command-line mistakes are refused (exit status 2) with what to write instead, never run with a default:
# the space-separated value of older releases, an unknown option, a switch given a value.
foreach(case "--sensor;DVS128;${fixture}|--sensor needs a value: write --sensor=VALUE"
             "--sensr=DVS128;${fixture}|unknown option --sensr=DVS128"
             "--json=yes;${fixture}|--json is a switch")
  string(REPLACE "|" ";" parts "${case}")
  list(POP_BACK parts expected)
  execute_process(COMMAND "${EVENT_INFO}" ${parts} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "${expected}")
    message(FATAL_ERROR "event_info ${parts}: exit status ${rc} and \"${err}\", expected 2 and \"${expected}\"")
  endif()
endforeach()
# A recording cut off inside its last line (a recorder stopped mid-write): what came before the cut is shown,
# then the error names the byte and the line (exit status 1).
set(cut "${WORK_DIR}/cut.txt")
file(WRITE "${cut}" "8 6\n0.001 1 2 1\n0.002 3 4 0\n0.003 7 5")
execute_process(COMMAND "${EVENT_INFO}" "${cut}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 1 OR NOT out MATCHES "events:    2 \\(ON 1, OFF 1\\)" OR NOT out MATCHES "error:     [^\n]*cut.txt: byte 28: line 4")
  message(FATAL_ERROR "a cut-off file gave exit status ${rc} and: ${out}")
endif()
