# Target settings the event module needs in both build modes (standalone and OpenCV extra module).
#
# - C++17 inside the module (public headers stay C++11-clean: OpenCV 4.6 builds its Python bindings and
#   other modules as C++11 and they include our headers);
# - Eigen3 (private): small dense least-squares in the estimators;
# - libusb-1.0 (optional, private): the live DAVIS back-end of EventCapture;
# - the location of the shared real recordings used by data-driven tests (they skip when it is absent).

get_filename_component(OPENCV_EVENT_MODULE_DIR "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)

find_package(Eigen3 QUIET NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  find_path(OPENCV_EVENT_EIGEN_INCLUDE_DIR Eigen/Core PATH_SUFFIXES eigen3)
  if(NOT OPENCV_EVENT_EIGEN_INCLUDE_DIR)
    message(FATAL_ERROR "opencv_event needs Eigen3 (Debian: apt-get install libeigen3-dev)")
  endif()
  add_library(Eigen3::Eigen INTERFACE IMPORTED)
  set_target_properties(Eigen3::Eigen PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${OPENCV_EVENT_EIGEN_INCLUDE_DIR}")
endif()

find_package(PkgConfig QUIET)
if(PKG_CONFIG_FOUND)
  pkg_check_modules(OPENCV_EVENT_LIBUSB QUIET IMPORTED_TARGET libusb-1.0)
  # AEDAT 4.0 packets are LZ4- or ZSTD-compressed.
  pkg_check_modules(OPENCV_EVENT_LZ4 QUIET IMPORTED_TARGET liblz4)
  pkg_check_modules(OPENCV_EVENT_ZSTD QUIET IMPORTED_TARGET libzstd)
  # ROS2 bags are sqlite3 databases.
  pkg_check_modules(OPENCV_EVENT_SQLITE3 QUIET IMPORTED_TARGET sqlite3)
endif()
find_package(BZip2 QUIET)  # ROS1 bag chunks
if(BZIP2_FOUND)
  set(OPENCV_EVENT_BZIP2_FOUND TRUE)
  message(STATUS "opencv_event: bzip2 found: ROS bag bz2 chunks enabled")
else()
  message(STATUS "opencv_event: bzip2 not found: ROS bag bz2 chunks cannot be read")
endif()
find_package(HDF5 QUIET COMPONENTS C)  # MVSEC recordings (optional)
if(HDF5_FOUND)
  set(OPENCV_EVENT_HDF5_FOUND TRUE)
  message(STATUS "opencv_event: HDF5 ${HDF5_VERSION} found: MVSEC-style HDF5 recordings enabled")
else()
  message(STATUS "opencv_event: HDF5 not found: MVSEC-style HDF5 recordings cannot be read")
endif()
foreach(dep LZ4 ZSTD SQLITE3)
  if(OPENCV_EVENT_${dep}_FOUND)
    message(STATUS "opencv_event: ${dep} ${OPENCV_EVENT_${dep}_VERSION} found: ${dep} support enabled (AEDAT 4.0 packets / ROS2 bags)")
  else()
    message(STATUS "opencv_event: ${dep} not found: files that need it (AEDAT 4.0 packets / ROS2 bags) cannot be read")
  endif()
endforeach()
if(OPENCV_EVENT_LIBUSB_FOUND)
  message(STATUS "opencv_event: libusb-1.0 ${OPENCV_EVENT_LIBUSB_VERSION} found: live DAVIS back-end enabled")
else()
  message(STATUS "opencv_event: libusb-1.0 not found: live DAVIS back-end disabled")
endif()

# Real recordings beside the checkout (never part of it); tests skip with a message when it is absent.
get_filename_component(OPENCV_EVENT_SHARED_DATA_DEFAULT "${CMAKE_CURRENT_LIST_DIR}/../../../../shared/data" ABSOLUTE)

function(opencv_event_configure_library target)
  set_target_properties(${target} PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
  target_include_directories(${target} PRIVATE "${OPENCV_EVENT_MODULE_DIR}/src")
  target_link_libraries(${target} PRIVATE Eigen3::Eigen)
  # A multiply followed by an add stays two roundings, as written, in every instruction set's copy: the plane
  # fit's vector kernels (AVX2, AVX-512 fuse them otherwise) then count exactly the scalar code's inliers, and
  # the lifetimes do not depend on the CPU.
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -ffp-contract=off)
  endif()
  foreach(dep LIBUSB LZ4 ZSTD SQLITE3)
    if(OPENCV_EVENT_${dep}_FOUND)
      target_link_libraries(${target} PRIVATE PkgConfig::OPENCV_EVENT_${dep})
      target_compile_definitions(${target} PRIVATE OPENCV_EVENT_HAVE_${dep}=1)
    endif()
  endforeach()
  opencv_event_link_test_codecs(${target})
endfunction()

# bzip2, sqlite3, LZ4, ZSTD and HDF5 are also linked into the tests: they write bz2 ROS bag chunks, ROS2 bag
# databases, compressed MCAP chunks and MVSEC fixture files.
function(opencv_event_link_test_codecs target)
  foreach(dep LZ4 ZSTD)
    if(OPENCV_EVENT_${dep}_FOUND)
      target_link_libraries(${target} PRIVATE PkgConfig::OPENCV_EVENT_${dep})
      target_compile_definitions(${target} PRIVATE OPENCV_EVENT_HAVE_${dep}=1)
    endif()
  endforeach()
  if(OPENCV_EVENT_SQLITE3_FOUND)
    target_link_libraries(${target} PRIVATE PkgConfig::OPENCV_EVENT_SQLITE3)
    target_compile_definitions(${target} PRIVATE OPENCV_EVENT_HAVE_SQLITE3=1)
  endif()
  if(OPENCV_EVENT_BZIP2_FOUND)
    target_link_libraries(${target} PRIVATE BZip2::BZip2)
    target_compile_definitions(${target} PRIVATE OPENCV_EVENT_HAVE_BZIP2=1)
  endif()
  opencv_event_link_hdf5(${target})
endfunction()

function(opencv_event_link_hdf5 target)
  if(OPENCV_EVENT_HDF5_FOUND)
    target_include_directories(${target} SYSTEM PRIVATE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
    target_link_libraries(${target} PRIVATE ${HDF5_C_LIBRARIES})
    target_compile_definitions(${target} PRIVATE OPENCV_EVENT_HAVE_HDF5=1)
  endif()
endfunction()

function(opencv_event_configure_test target)
  set_target_properties(${target} PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON CXX_EXTENSIONS OFF)
  opencv_event_link_test_codecs(${target})
  # Unit tests of internal classes include their headers as the library does ("stereo/zou_descriptor_map.hpp").
  target_include_directories(${target} PRIVATE "${OPENCV_EVENT_MODULE_DIR}/src")
  # The repository root: tests read its committed fixtures (the fuzzers' seed files, test/fuzz/corpus).
  get_filename_component(OPENCV_EVENT_SOURCE_ROOT "${OPENCV_EVENT_MODULE_DIR}/../.." ABSOLUTE)
  # Both paths in one generated source of the target's own, not in compile definitions: those would be in every
  # test object's command line, and a fresh clone (another path) would then miss ccache for all of them.
  set(paths_source "${CMAKE_CURRENT_BINARY_DIR}/${target}_paths.cpp")
  configure_file("${OPENCV_EVENT_MODULE_DIR}/test/test_paths.cpp.in" "${paths_source}" @ONLY)
  target_sources(${target} PRIVATE "${paths_source}")
endfunction()
