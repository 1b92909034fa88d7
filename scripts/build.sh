#!/usr/bin/env bash
# Configures and builds the standalone mode (against the installed OpenCV) in build/ with ccache.
#   scripts/build.sh [extra cmake args...]
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cache=${OPENCV_EVENT_CACHE:-/var/cache/opencv_event}
export CCACHE_DIR=${CCACHE_DIR:-$cache/ccache}
export CCACHE_BASEDIR=$repo  # paths relative to the clone: a fresh clone compiles from the cache
src=$(cat "$cache/opencv-source-dir" 2>/dev/null || true)
[ -n "$src" ] || { echo "build.sh: run scripts/setup.sh first" >&2; exit 1; }
cmake -S "$repo" -B "$repo/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  -DOPENCV_EVENT_OPENCV_SOURCE_DIR="$src" "$@" > "$repo/build.configure.log" 2>&1 \
  || { cat "$repo/build.configure.log"; exit 1; }
cmake --build "$repo/build"
