# The Python package opencv_event's own files, in both build modes: its Python code (misc/python/opencv_event) and
# _version.py (the project's version, from the top-level CMakeLists.txt), copied into `package_dir` and installed
# into `install_dir`. Its native part is the standalone build's extension, or cv2.event in an OpenCV build.
function(opencv_event_python_package_files package_dir install_dir)
  set(pysrc "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../misc/python/opencv_event")
  file(STRINGS "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../../../CMakeLists.txt" project_line
       REGEX "^project\\(opencv_event VERSION [0-9.]+")
  string(REGEX REPLACE ".* VERSION ([0-9.]+).*" "\\1" version "${project_line}")
  file(GLOB py_files CONFIGURE_DEPENDS "${pysrc}/*.py")
  foreach(f ${py_files})
    get_filename_component(name "${f}" NAME)
    configure_file("${f}" "${package_dir}/${name}" COPYONLY)
  endforeach()
  file(WRITE "${package_dir}/_version.py.tmp" "__version__ = \"${version}\"\n")
  configure_file("${package_dir}/_version.py.tmp" "${package_dir}/_version.py" COPYONLY)
  file(REMOVE "${package_dir}/_version.py.tmp")
  install(FILES ${py_files} "${package_dir}/_version.py" DESTINATION "${install_dir}/opencv_event" ${ARGN})
endfunction()
