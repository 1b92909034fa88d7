# ctest `consumer_project`: install the standalone build, build test/consumer against the installed
# package with find_package(opencv_event), and run it. Fails on any step.
foreach(v BUILD_DIR CONSUMER_SOURCE_DIR WORK_DIR)
  if(NOT ${v})
    message(FATAL_ERROR "consumer_project.cmake: ${v} not set")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/install")

include("${CMAKE_CURRENT_LIST_DIR}/run_step.cmake")

set(config_args)
if(CONFIG)
  set(config_args --config ${CONFIG})
endif()
run_step(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}" ${config_args})
run_step(${CMAKE_COMMAND} -S "${CONSUMER_SOURCE_DIR}" -B "${WORK_DIR}/build"
         "-DCMAKE_PREFIX_PATH=${prefix}" -DCMAKE_BUILD_TYPE=Release)
run_step(${CMAKE_COMMAND} --build "${WORK_DIR}/build" ${config_args})
find_program(consumer NAMES event_consumer PATHS "${WORK_DIR}/build" "${WORK_DIR}/build/Release" NO_DEFAULT_PATH)
if(NOT consumer)
  message(FATAL_ERROR "event_consumer was not built")
endif()
run_step("${consumer}")
