"""pip's way in: builds the Python package opencv_event with the standalone CMake build (see pyproject.toml).

The extension is compiled by CMake exactly as `cmake --build` does it (OpenCV's binding generator on the module's
headers, against the installed OpenCV); the library libopencv_event goes into the package beside it, so the wheel
needs nothing of this repository once installed. Needs what scripts/setup.sh installs, including the OpenCV source
tree it fetches (OPENCV_EVENT_OPENCV_SOURCE_DIR, else the one scripts/setup.sh recorded).
"""
import glob
import os
import re
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))


def project_version():
    with open(os.path.join(HERE, "CMakeLists.txt")) as f:
        return re.search(r"project\(opencv_event VERSION ([0-9.]+)", f.read()).group(1)


def opencv_source_dir():
    source = os.environ.get("OPENCV_EVENT_OPENCV_SOURCE_DIR")
    if not source:
        recorded = os.path.join(os.environ.get("OPENCV_EVENT_CACHE", "/var/cache/opencv_event"), "opencv-source-dir")
        if os.path.exists(recorded):
            with open(recorded) as f:
                source = f.read().strip()
    if not source:
        sys.exit("opencv_event: the Python bindings need the OpenCV source tree of the installed OpenCV: run "
                 "scripts/setup.sh, or set OPENCV_EVENT_OPENCV_SOURCE_DIR")
    return source


class BuildWithCMake(build_py):
    """The package's Python files as usual, plus the extension and libopencv_event built by CMake."""

    def run(self):
        super().run()
        # Beside build/ (the same depth below the repository): ccache, with its base dir at the repository, then
        # sees the same relative paths as in scripts/build.sh's build and reuses its objects.
        build = os.path.join(HERE, "build-pip")
        launcher = ["-DCMAKE_C_COMPILER_LAUNCHER=ccache", "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"] if shutil.which("ccache") else []
        launcher += ["-G", "Ninja"] if shutil.which("ninja") else []  # as scripts/build.sh: the same compile lines
        subprocess.check_call(["cmake", "-S", HERE, "-B", build, "-DCMAKE_BUILD_TYPE=Release"] + launcher + [
                               "-DOPENCV_EVENT_OPENCV_SOURCE_DIR=" + opencv_source_dir(),
                               "-DPython3_EXECUTABLE=" + sys.executable, "-DOPENCV_EVENT_PYTHON_BUNDLE_LIBRARY=ON",
                               "-DOPENCV_EVENT_BUILD_TESTS=OFF", "-DOPENCV_EVENT_BUILD_PERF_TESTS=OFF",
                               "-DOPENCV_EVENT_BUILD_SAMPLES=OFF", "-DOPENCV_EVENT_BUILD_BENCHMARKS=OFF",
                               "-DOPENCV_EVENT_BUILD_CONTRIB_TEST=OFF"])
        subprocess.check_call(["cmake", "--build", build, "--target", "opencv_event_python", "--parallel"])
        target = os.path.join(self.build_lib, "opencv_event")
        built = os.path.join(build, "python", "opencv_event")
        for path in glob.glob(os.path.join(built, "_bindings*")) + [os.path.join(built, "_version.py")]:
            shutil.copy2(path, target)
        # The library under its soname, where the extension's $ORIGIN run path finds it.
        for path in glob.glob(os.path.join(build, "modules", "event", "libopencv_event.so.*")):
            if os.path.islink(path):
                shutil.copy2(os.path.realpath(path), os.path.join(target, os.path.basename(path)))


setup(version=project_version(), cmdclass={"build_py": BuildWithCMake},
      options={"build": {"build_base": os.path.join("build", "pip")}},  # beside, not inside, CMake's build/ tree
      package_data={"opencv_event": ["_bindings*", "_version.py", "libopencv_event.so.*"]})
