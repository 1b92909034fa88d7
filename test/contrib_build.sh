#!/usr/bin/env bash
# Build mode B: OpenCV from source with this repository's modules/ as an extra module, then run
# opencv_test_event and a quick opencv_perf_event pass. Registered in ctest as `contrib_build`.
#
#   test/contrib_build.sh <opencv-source-dir> [build-dir]
#
# The build dir lives outside the clone (default: $OPENCV_EVENT_CACHE/contrib-build) and ccache is used, so
# repeated runs only recompile what changed. The Debian source package has no 3rdparty/: everything that would
# need it is switched off; PNG/JPEG/zlib come from the system.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
src=${1:?usage: contrib_build.sh <opencv-source-dir> [build-dir]}
cache=${OPENCV_EVENT_CACHE:-/var/cache/opencv_event}
build=${2:-$cache/contrib-build}
export CCACHE_DIR=${CCACHE_DIR:-$cache/ccache}
mkdir -p "$build" "$CCACHE_DIR"

launcher=()
if command -v ccache >/dev/null; then
  launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
fi
generator=()
if command -v ninja >/dev/null; then generator=(-G Ninja); fi
# A build dir made from another source tree or by another generator cannot be reused.
if [ -f "$build/CMakeCache.txt" ] && { ! grep -qx "CMAKE_HOME_DIRECTORY:INTERNAL=$src" "$build/CMakeCache.txt" ||
     ! grep -qx "CMAKE_GENERATOR:INTERNAL=${generator[1]:-Unix Makefiles}" "$build/CMakeCache.txt"; }; then
  echo "== contrib_build: $build was configured for another source tree or generator: starting afresh"
  rm -rf "$build"; mkdir -p "$build"
fi

modules=core,imgproc,imgcodecs,videoio,highgui,flann,features2d,calib3d,ts,event
# Python bindings (cv2 with cv2.event) when Debian's python3 with numpy is there: proves WRAP python works.
python=(-DBUILD_opencv_python3=OFF)
if /usr/bin/python3 -c "import numpy, os, sysconfig; assert os.path.exists(os.path.join(sysconfig.get_paths()['include'], 'Python.h'))" 2>/dev/null; then
  py() { /usr/bin/python3 -c "$1"; }
  python=(-DBUILD_opencv_python3=ON -DPYTHON3_EXECUTABLE=/usr/bin/python3
          -DPYTHON3_INCLUDE_DIR="$(py 'import sysconfig; print(sysconfig.get_paths()["include"])')"
          -DPYTHON3_LIBRARY="$(py 'import sysconfig, os; print(os.path.join(sysconfig.get_config_var("LIBDIR"), sysconfig.get_config_var("LDLIBRARY")))')"
          -DPYTHON3_NUMPY_INCLUDE_DIRS="$(py 'import numpy; print(numpy.get_include())')")
  modules="$modules,python3,python_bindings_generator"
  # OpenCV caches what it found of Python: drop a stale result (another interpreter) before configuring.
  version=$(py 'import platform; print(platform.python_version())')
  if [ -f "$build/CMakeCache.txt" ] && ! grep -qx "PYTHON3_VERSION_STRING:INTERNAL=$version" "$build/CMakeCache.txt"; then
    python=(-U "PYTHON3*" -U "OPENCV_PYTHON3*" "${python[@]}")  # -U first: it would also drop the -D given before it
  fi
fi

off=()
for w in OPENJPEG JASPER QUIRC IPP ITT ADE PROTOBUF GTK QT FFMPEG GSTREAMER V4L 1394 OPENCL VA VA_INTEL \
         TIFF WEBP OPENEXR CAROTENE LAPACK TBB OPENMP VTK CUDA OPENGL GDAL GPHOTO2 ONNX VULKAN IMGCODEC_HDR \
         IMGCODEC_SUNRASTER IMGCODEC_PFM LIBREALSENSE OPENNI2 XINE; do
  off+=("-DWITH_$w=OFF")
done

# The module is built from a copy of the repository in a fixed place under the cache, where only the files whose
# content changed are written: from a new clone, ninja and ccache then see the same paths and recompile what
# changed, not the whole module (the clone's own path would be new to both every time). The copy keeps the
# repository's layout (the module reads the version from its CMakeLists.txt and the tests read its fixtures),
# and a link beside it leads to the recordings beside the clone (../shared/data, when there).
copy=$cache/contrib-repository
git -C "$repo" rev-parse --git-dir > /dev/null 2>&1 \
  || { echo "contrib_build: $repo is not a git checkout (the copy takes the files git sees)" >&2; exit 1; }
mkdir -p "$copy"
git -C "$repo" ls-files --cached --others --exclude-standard -z | sort -z > "$build/repository-files"
while IFS= read -r -d '' f; do
  [ -f "$repo/$f" ] || continue  # a file deleted in the working tree but not in the index
  mkdir -p "$copy/$(dirname "$f")"
  cmp -s "$repo/$f" "$copy/$f" || cp "$repo/$f" "$copy/$f"
done < "$build/repository-files"
(cd "$copy" && find . -type f -printf '%P\0' | sort -z) | comm -z -23 - "$build/repository-files" \
  | while IFS= read -r -d '' f; do rm -f "$copy/$f"; done
if [ -d "$repo/../shared" ]; then ln -sfn "$(cd "$repo/../shared" && pwd -P)" "$(dirname "$copy")/shared"; else rm -f "$(dirname "$copy")/shared"; fi

echo "== contrib_build: configuring OpenCV $(basename "$src") with $repo/modules (copied to $copy) in $build"
cmake -S "$src" -B "$build" "${generator[@]}" "${launcher[@]}" "${off[@]}" \
  -DCMAKE_BUILD_TYPE=Release \
  -DOPENCV_EXTRA_MODULES_PATH="$copy/modules" \
  -DBUILD_LIST="$modules" \
  -DBUILD_TESTS=ON -DBUILD_PERF_TESTS=ON \
  -DOPENCV_BUILD_TEST_MODULES_LIST=event -DOPENCV_BUILD_PERF_TEST_MODULES_LIST=event \
  -DBUILD_EXAMPLES=OFF -DBUILD_opencv_apps=OFF -DBUILD_DOCS=OFF -DBUILD_JAVA=OFF \
  -DBUILD_opencv_python2=OFF "${python[@]}" \
  -DBUILD_ZLIB=OFF -DBUILD_PNG=OFF -DBUILD_JPEG=OFF -DWITH_PNG=ON -DWITH_JPEG=ON -DWITH_EIGEN=ON \
  -DCPU_DISPATCH= -DOPENCV_GENERATE_PKGCONFIG=OFF -DENABLE_PRECOMPILED_HEADERS=OFF \
  > "$build/configure.log" 2>&1 || { tail -50 "$build/configure.log"; exit 1; }
grep -E "opencv_event|To be built" "$build/configure.log" || true

echo "== contrib_build: building (log: $build/build.log)"
targets=(opencv_test_event opencv_perf_event)
if [[ " ${python[*]} " == *" -DBUILD_opencv_python3=ON "* ]]; then targets+=(opencv_python3); fi
cmake --build "$build" --target "${targets[@]}" > "$build/build.log" 2>&1 \
  || { tail -80 "$build/build.log"; exit 1; }
if command -v ccache >/dev/null; then ccache -s | grep -Ei "hit|miss" | head -4 || true; fi

echo "== contrib_build: opencv_test_event"
# The same sources as the standalone build's opencv_test_event, which runs every test: here all but the long
# accuracy runs and five of the six row-band cases (long_tests.sh), which add nothing that depends on how the
# module was built.
source "$here/long_tests.sh"
bash "$here/gtest_shards.sh" "$build/bin/opencv_test_event" \
  --gtest_filter="-$long_accuracy_tests:Event_Extremes.state_does_not_grow_with_the_number_of_events:$(row_band_cases 0 1 2 4 5)"
if [[ " ${python[*]} " == *" -DBUILD_opencv_python3=ON "* ]]; then
  # The same Python API as the standalone build's (both from OpenCV's generator on the same headers).
  standalone_signatures="$repo/build/python_generated/pyopencv_signatures.json"
  if [ -f "$standalone_signatures" ]; then
    /usr/bin/python3 "$here/compare_python_signatures.py" "$standalone_signatures" \
      "$build/modules/python_bindings_generator/pyopencv_signatures.json"
  else
    echo "== contrib_build: SKIP comparing the Python API with the standalone build's: $standalone_signatures not built"
  fi
  # The package opencv_event on this build's cv2.event: the same pytest suites as the standalone build's ctests
  # python_package and python_sample (the command-line tools they compare with come from the standalone build
  # when it is there).
  echo "== contrib_build: the Python package opencv_event on cv2.event (pytest)"
  PYTHONPATH="$(dirname "$(find "$build/lib" -name 'cv2*.so' -print -quit)")" PYTHONDONTWRITEBYTECODE=1 \
    OPENCV_EVENT_BUILD_MODE=contrib OPENCV_EVENT_TOOLS="${OPENCV_EVENT_TOOLS:-$repo/build/samples}" \
    /usr/bin/python3 -m pytest -q -rs -p no:cacheprovider "$repo/modules/event/misc/python/test" "$repo/test/python"
else
  echo "== contrib_build: SKIP the Python bindings: /usr/bin/python3 with numpy and Python.h not found (scripts/setup.sh installs them)"
fi
echo "== contrib_build: opencv_perf_event (one sample each: proves the perf tests run, not a timing)"
# sed reads the whole list: head would exit after 20 lines, and the lister's SIGPIPE fail the pipeline.
"$build/bin/opencv_perf_event" --gtest_list_tests | sed -n '1,20p'
"$build/bin/opencv_perf_event" --perf_min_samples=1 --perf_force_samples=1 --perf_time_limit=1
