# The OpenCV source tree of the installed OpenCV version (Debian: `apt-get source opencv`, fetched by
# scripts/setup.sh): the standalone build compiles ts from it for the tests and runs its Python binding
# generator for the Python extension. Both must match the installed headers exactly.

set(OPENCV_EVENT_OPENCV_SOURCE_DIR "" CACHE PATH
    "OpenCV source tree of the installed OpenCV version (ts for the tests, the binding generator for Python)")

# Stops with a message naming `why` and the options that avoid the need (`instead`) unless
# OPENCV_EVENT_OPENCV_SOURCE_DIR holds `probe` and is the installed OpenCV's version.
function(opencv_event_require_opencv_source why probe instead)
  set(src "${OPENCV_EVENT_OPENCV_SOURCE_DIR}")
  if(NOT src OR NOT EXISTS "${src}/${probe}")
    message(FATAL_ERROR
      "opencv_event: ${why}. Set -DOPENCV_EVENT_OPENCV_SOURCE_DIR=<opencv-${OpenCV_VERSION} source tree> "
      "(scripts/setup.sh fetches it with `apt-get source opencv`), or configure with ${instead}.")
  endif()
  file(STRINGS "${src}/modules/core/include/opencv2/core/version.hpp" _ver_lines
       REGEX "^#define CV_VERSION_(MAJOR|MINOR|REVISION)[ \t]+[0-9]+")
  set(_src_version "")
  foreach(_part MAJOR MINOR REVISION)
    foreach(_line ${_ver_lines})
      if(_line MATCHES "CV_VERSION_${_part}[ \t]+([0-9]+)")
        list(APPEND _src_version "${CMAKE_MATCH_1}")
      endif()
    endforeach()
  endforeach()
  string(REPLACE ";" "." _src_version "${_src_version}")
  if(NOT _src_version VERSION_EQUAL OpenCV_VERSION)
    message(FATAL_ERROR "opencv_event: ${src} is OpenCV ${_src_version}, but the installed OpenCV is "
                        "${OpenCV_VERSION}: ${why} of the installed version.")
  endif()
endfunction()
