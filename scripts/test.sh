#!/usr/bin/env bash
# README command 2: install dependencies, build both modes, run every test.
#   bash scripts/test.sh
# Standalone build -> ctest: opencv_test_event, the perf-test smoke run, the downstream consumer project and
# contrib_build (OpenCV from source with modules/ as an extra module: opencv_test_event + opencv_perf_event
# there). The ordinary tests run as many at a time as the machine has cores (the sanitizer, fuzz and contrib
# stages alone: they shard their own runs). Ends with ctest's summary line.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
start=$(date +%s)
bash "$repo/scripts/setup.sh"
bash "$repo/scripts/build.sh" -DOPENCV_EVENT_BUILD_CONTRIB_TEST=ON
cd "$repo/build"
ctest --output-on-failure --timeout 3600 -j "$(nproc)" "$@"
echo "== test.sh: all tests passed in $(( $(date +%s) - start )) s"
