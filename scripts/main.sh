#!/usr/bin/env bash
# README command 1: install dependencies, build, run the main job; results in output/.
#   bash scripts/main.sh
# Today the main job is event_stereo_overview on the default stereo recording: the real DVS128 pair
# ../shared/data/stereo_dvs128_tum/Fan_disp8.dat when it is there, else a synthetic recording the sample
# writes itself. It writes left | right time-surface pictures and output/summary.md.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$repo/scripts/setup.sh"
bash "$repo/scripts/build.sh" -DOPENCV_EVENT_BUILD_CONTRIB_TEST=OFF
out="$repo/output"
mkdir -p "$out"
fan="${OPENCV_EVENT_SHARED_DATA:-$repo/../shared/data}/stereo_dvs128_tum/Fan_disp8.dat"
if [ -f "$fan" ]; then
  # TUM stereo DVS128: t_us x y p retina, retina 1 = left camera.
  "$repo/build/samples/event_stereo_overview" --input "$fan" --left-camera-value 1 --sensor DVS128 --output "$out"
else
  "$repo/build/samples/event_stereo_overview" --output "$out"
fi
echo "== main.sh: pictures and summary.md in $out"
