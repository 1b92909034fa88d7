# CPU dispatch of the module's *.simd.hpp files (universal intrinsics compiled once per instruction set).
#
# Inside an OpenCV source build, OpenCV's own ocv_add_dispatched_file does it, over the instruction sets that
# build dispatches to. Standalone, against an installed OpenCV, opencv_event_add_dispatched_file does the same:
# for each of the instruction sets the compiler supports beyond the baseline, a generated
# <name>.<set>.cpp compiles the .simd.hpp with that set's flags into namespace opt_<SET>, and a generated
# <name>.simd_declarations.hpp declares them for the dispatcher (src/common/cpu_dispatch.hpp).

# x86-64 flags and the CV_* feature macros of each set (the installed OpenCV headers take them from these).
set(OPENCV_EVENT_DISPATCH_AVX2_FLAGS -mavx2 -mfma -mf16c -mpopcnt -msse4.2)
set(OPENCV_EVENT_DISPATCH_AVX2_DEFINITIONS CV_AVX2=1 CV_AVX=1 CV_FMA3=1 CV_FP16=1 CV_POPCNT=1 CV_SSE3=1 CV_SSSE3=1
    CV_SSE4_1=1 CV_SSE4_2=1)
set(OPENCV_EVENT_DISPATCH_AVX512_SKX_FLAGS ${OPENCV_EVENT_DISPATCH_AVX2_FLAGS} -mavx512f -mavx512cd -mavx512vl -mavx512bw
    -mavx512dq)
set(OPENCV_EVENT_DISPATCH_AVX512_SKX_DEFINITIONS ${OPENCV_EVENT_DISPATCH_AVX2_DEFINITIONS} CV_AVX512_SKX=1
    CV_AVX_512F=1 CV_AVX_512CD=1 CV_AVX_512VL=1 CV_AVX_512BW=1 CV_AVX_512DQ=1)

# Writes a generated file only when its content changes, so that an unchanged one does not trigger rebuilds.
function(opencv_event_write_if_changed path content)
  set(old "")
  if(EXISTS "${path}")
    file(READ "${path}" old)
  endif()
  if(NOT old STREQUAL content)
    file(WRITE "${path}" "${content}")
  endif()
endfunction()

# opencv_event_add_dispatched_file(<target> <path under src/ without .simd.hpp> <SET>...)
function(opencv_event_add_dispatched_file target name)
  include(CheckCXXCompilerFlag)
  set(src_dir "${OPENCV_EVENT_MODULE_DIR}/src")
  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/dispatch")
  set(declarations "#define CV_CPU_SIMD_FILENAME \"${src_dir}/${name}.simd.hpp\"\n")
  set(modes "BASELINE")
  set(x86_64 FALSE)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$" AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    set(x86_64 TRUE)
  endif()
  foreach(set_name ${ARGN})
    if(NOT x86_64 OR NOT DEFINED OPENCV_EVENT_DISPATCH_${set_name}_FLAGS)
      continue()  # elsewhere (AArch64: NEON is the baseline) the baseline copy is the vector one
    endif()
    string(REPLACE ";" " " flags "${OPENCV_EVENT_DISPATCH_${set_name}_FLAGS}")
    string(MAKE_C_IDENTIFIER "OPENCV_EVENT_HAVE_FLAGS_${set_name}" have_flags)
    set(CMAKE_REQUIRED_QUIET ON)
    check_cxx_compiler_flag("${flags}" ${have_flags})
    if(NOT ${have_flags})
      message(STATUS "opencv_event: the compiler has no ${set_name} flags: ${name} without ${set_name}")
      continue()
    endif()
    string(TOLOWER "${set_name}" lower)
    set(cpp "${out_dir}/${name}.${lower}.cpp")
    opencv_event_write_if_changed("${cpp}" "#include \"precomp.hpp\"\n#include \"${name}.simd.hpp\"\n")
    target_sources(${target} PRIVATE "${cpp}")
    set_source_files_properties("${cpp}" PROPERTIES
      COMPILE_OPTIONS "${OPENCV_EVENT_DISPATCH_${set_name}_FLAGS}"
      COMPILE_DEFINITIONS "CV_CPU_DISPATCH_MODE=${set_name};${OPENCV_EVENT_DISPATCH_${set_name}_DEFINITIONS}")
    string(APPEND declarations "#define CV_CPU_DISPATCH_MODE ${set_name}\n#include \"common/cpu_dispatch_declarations.hpp\"\n")
    set(modes "${set_name}, ${modes}")
  endforeach()
  string(APPEND declarations "#define CV_CPU_DISPATCH_MODES_ALL ${modes}\n\n#undef CV_CPU_SIMD_FILENAME\n")
  opencv_event_write_if_changed("${out_dir}/${name}.simd_declarations.hpp" "${declarations}")
  target_include_directories(${target} PRIVATE "${out_dir}")
  message(STATUS "opencv_event: ${name} dispatched to ${modes}")
endfunction()
