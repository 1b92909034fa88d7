#!/usr/bin/env bash
# README command 1: install dependencies, build, run the main job; results in output/.
#   bash scripts/main.sh
# The main job is event_stereo, per-event stereo disparity, depth and lifetime (COUPLED mode):
#   1. on the built-in default recording: the simulator's "boxes" scene (1 s: two boxes and a pole at three
#      depths over a plain wall, on a real sensor's noise and misalignment), scored against its ground truth
#      -> output/simulated: events.csv, disparity_NNNNN.png, disparity.avi, summary.md, and boxes.aedat4 (+ .gt.csv:
#      the scene as a recording with its ground truth);
#   2. on the real DVS128 pair ../shared/data/stereo_dvs128_tum/Fan_disp8.dat when it is there
#      -> output/tum_fan.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$repo/scripts/setup.sh"
bash "$repo/scripts/build.sh" -DOPENCV_EVENT_BUILD_CONTRIB_TEST=OFF
out="$repo/output"
mkdir -p "$out"
# --record: the same events as a recording with its ground truth, for the Python quick-start (doc/python.md).
"$repo/build/samples/event_stereo" --scene=boxes --output="$out/simulated" --record="$out/simulated/boxes.aedat4"
fan="${OPENCV_EVENT_SHARED_DATA:-$repo/../shared/data}/stereo_dvs128_tum/Fan_disp8.dat"
if [ -f "$fan" ]; then
  # TUM stereo DVS128: t_us x y p retina, retina 1 = left camera.
  "$repo/build/samples/event_stereo" --input="$fan" --left-camera-value=1 --sensor=DVS128 --output="$out/tum_fan"
fi
echo "== main.sh: events.csv, pictures and summary.md in $out/simulated${fan:+ and $out/tum_fan}"
