# ctest `event_player_frames`: event_player on a small stereo fixture writes left | right frames enlarged to at
# least 512 px across by default (8 x 6 pixels: 64 times, 1024 x 384 for the pair), or by --zoom; a negative
# zoom is refused; a file without a sensor size is refused with the option to give; events outside the sensor
# are reported.
foreach(v EVENT_PLAYER WORK_DIR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "event_player.cmake: ${v} not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(fixture "${WORK_DIR}/stereo.txt")
file(WRITE "${fixture}" "# fixture\n8 6\n0.001 1 2 1 0\n0.002 3 4 0 1\n0.040 7 5 1 1\n")

# The width and height a PNG's header gives (bytes 16..23, big-endian).
function(png_size path out)
  if(NOT EXISTS "${path}")
    message(FATAL_ERROR "${path} was not written")
  endif()
  file(READ "${path}" hex OFFSET 16 LIMIT 8 HEX)
  string(SUBSTRING "${hex}" 0 8 w)
  string(SUBSTRING "${hex}" 8 8 h)
  math(EXPR w "0x${w}")
  math(EXPR h "0x${h}")
  set(${out} "${w}x${h}" PARENT_SCOPE)
endfunction()

foreach(case "auto;--zoom=0;1024x384" "two;--zoom=2;32x12")
  list(GET case 0 name)
  list(GET case 1 option)
  list(GET case 2 expected)
  execute_process(COMMAND "${EVENT_PLAYER}" "${fixture}" ${option} "--output=${WORK_DIR}/${name}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "event_player ${option} failed (${rc})")
  endif()
  # Two windows of 33 ms: the events at 1-2 ms and at 40 ms.
  foreach(frame frame_00000.png frame_00001.png)
    png_size("${WORK_DIR}/${name}/${frame}" size)
    if(NOT size STREQUAL expected)
      message(FATAL_ERROR "${name}/${frame} is ${size}, expected ${expected}")
    endif()
  endforeach()
  if(EXISTS "${WORK_DIR}/${name}/frame_00002.png")
    message(FATAL_ERROR "${name}: more frames than the recording's two windows")
  endif()
endforeach()

execute_process(COMMAND "${EVENT_PLAYER}" "${fixture}" --zoom=-1 "--output=${WORK_DIR}/negative"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "--zoom=-1")
  message(FATAL_ERROR "a negative zoom was not refused (${rc}): ${err}")
endif()

# A recording without its sensor size is refused with the option to give; given it, it plays.
set(no_size "${WORK_DIR}/no_size.txt")
file(WRITE "${no_size}" "0.001 1 2 1 0\n0.002 3 4 0 1\n")
execute_process(COMMAND "${EVENT_PLAYER}" "${no_size}" "--output=${WORK_DIR}/no_size" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(rc EQUAL 0 OR NOT err MATCHES "no_size.txt: the file does not record the sensor size; pass --sensor=WxH")
  message(FATAL_ERROR "a file without a sensor size gave exit status ${rc} and: ${err}")
endif()
execute_process(COMMAND "${EVENT_PLAYER}" "${no_size}" --sensor=4x5 --zoom=1 "--output=${WORK_DIR}/given_size" RESULT_VARIABLE rc ERROR_VARIABLE err)
png_size("${WORK_DIR}/given_size/frame_00000.png" size)
if(NOT rc EQUAL 0 OR NOT size STREQUAL "8x5")
  message(FATAL_ERROR "with --sensor=4x5: exit status ${rc}, frame ${size} (expected 8x5, left | right): ${err}")
endif()

# Events outside the sensor are reported, like event_stereo and event_info do: here one of three (x = 9 on an
# 8 x 6 sensor).
set(outside "${WORK_DIR}/outside.txt")
file(WRITE "${outside}" "8 6\n0.001 1 2 1 0\n0.002 9 4 0 1\n0.003 7 5 1 1\n")
execute_process(COMMAND "${EVENT_PLAYER}" "${outside}" "--output=${WORK_DIR}/outside" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT err MATCHES "warning: 1 input events lie outside the 8 x 6 sensor and were not processed")
  message(FATAL_ERROR "an event outside the sensor: exit status ${rc} and: ${err}")
endif()
