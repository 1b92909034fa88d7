#!/usr/bin/env bash
# ctest `event_lifetime_sample`: the event_lifetime sample on the simulated moving line (75 px/s: the line is
# 0.45 m/s at 1.2 m seen with f = 200 px) writes one CSV row per event whose median lifetime is the closed-form
# 1 / 75 s = 13333 us (within 10 %), and pictures; its lifetime check (the edge reaching the next pixel after
# one lifetime) prints a median within 15 % of 1. --duration-ms and --sensor-set shape the simulated scene: 600 ms
# of it end within the last 10 ms before 600 ms, thresholds four times the preset's fire fewer than half as many
# events, and --sensor-set with a recording is refused.
set -euo pipefail
sample=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
"$sample" --scene=moving_line --output="$work" --csv="$work/events.csv" --max-ms=300 > "$work/stdout.txt" 2> "$work/stderr.txt"
head -1 "$work/events.csv" | grep -qx "t,x,y,p,lifetime_us,vx,vy,status,quality" || { echo "bad CSV header"; exit 1; }
rows=$(($(wc -l < "$work/events.csv") - 1))
[ "$rows" -gt 10000 ] || { echo "only $rows events"; exit 1; }
median=$(awk -F, 'NR > 1 && $8 != 0 { print $5 }' "$work/events.csv" | sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
awk -v m="$median" 'BEGIN { e = (m - 13333.3) / 13333.3; if (e < -0.1 || e > 0.1) exit 1 }' \
  || { echo "median lifetime $median us, expected 13333 us +/- 10 %"; exit 1; }
ls "$work"/active_*.png > /dev/null || { echo "no pictures"; exit 1; }
check=$(sed -n 's/^lifetime check: the edge reached the next pixel after \([0-9.]*\) lifetimes.*/\1/p' "$work/stdout.txt")
[ -n "$check" ] || { echo "no lifetime check printed"; cat "$work/stdout.txt"; exit 1; }
awk -v c="$check" 'BEGIN { if (c < 0.85 || c > 1.15) exit 1 }' \
  || { echo "lifetime check median $check, expected 1 +/- 15 %"; exit 1; }
events() { sed -n 's/^\([0-9]*\) events of camera 0:.*/\1/p' "$1"; }
"$sample" --scene=moving_line --output="$work/long" --csv="$work/long.csv" --duration-ms=600 > "$work/long.txt" 2> /dev/null
last=$(tail -1 "$work/long.csv" | cut -d, -f1)
[ "$last" -gt 590000 ] && [ "$last" -le 600000 ] || { echo "--duration-ms=600: last event at $last us"; exit 1; }
"$sample" --scene=moving_line --output="$work/coarse" --duration-ms=600 --sensor-set=thresholdOn=0.8,thresholdOff=0.8 \
  > "$work/coarse.txt" 2> /dev/null
[ $(($(events "$work/coarse.txt") * 2)) -lt "$(events "$work/long.txt")" ] \
  || { echo "thresholds of 0.8: $(events "$work/coarse.txt") events against $(events "$work/long.txt")"; exit 1; }
if "$sample" "$work/long/moving_line.aedat4" --output="$work/refused" --sensor-set=blurSigmaPx=0.6 > /dev/null 2> "$work/refused.txt" \
  || ! grep -q -- "--sensor-set: only for a simulated scene" "$work/refused.txt"; then
  echo "--sensor-set with a recording was not refused"; cat "$work/refused.txt"; exit 1
fi
echo "event_lifetime: $rows events, median lifetime $median us (expected 13333), lifetime check $check (expected 1)"
