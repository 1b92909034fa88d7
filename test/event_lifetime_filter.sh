#!/usr/bin/env bash
# ctest `event_lifetime_filter`: event_lifetime --filter=anti_flicker on the simulated boxes_flicker scene (the
# boxes lit by a lamp at 100 Hz). Against the simulator's truth (the recording's .gt.csv, joined by t, x, y, p):
# the left camera's events are the ones the filter reports reading, the CSV holds the ones it reports keeping,
# at least 99 % of the motion events (no noise, no flicker flag) are kept and at most 10 % of the flicker events;
# the lifetime check over the kept events prints a median within 10 % of 1 (perfect lifetimes give 1).
set -euo pipefail
sample=$1
work=$2
rm -rf "$work" && mkdir -p "$work"
"$sample" --scene=boxes_flicker --filter=anti_flicker --output="$work" --csv="$work/events.csv" --every-ms=250 \
  > "$work/stdout.txt" 2> "$work/stderr.txt"
line=$(grep "^filter anti_flicker: kept" "$work/stdout.txt") || { echo "no filter line"; cat "$work/stdout.txt"; exit 1; }
kept=$(echo "$line" | sed -n 's/^filter anti_flicker: kept \([0-9]*\) of \([0-9]*\) events.*/\1/p')
delivered=$(echo "$line" | sed -n 's/^filter anti_flicker: kept \([0-9]*\) of \([0-9]*\) events.*/\2/p')
rows=$(($(wc -l < "$work/events.csv") - 1))
[ "$rows" -eq "$kept" ] || { echo "CSV has $rows events, the filter reports keeping $kept"; exit 1; }
# Columns of the truth: t,x,y,p,camera,depth,disparity,flow_x,flow_y,lifetime,flags (1 noise, 4 flicker).
counts=$(awk -F, 'FNR == 1 { next }
  FILENAME ~ /events.csv$/ { kept[$1 "," $2 "," $3 "," $4] = 1; next }
  $5 == 0 { key = $1 "," $2 "," $3 "," $4; flags = int($11); left++
            if (flags == 0) { motion++; motionKept += (key in kept) }
            if (int(flags / 4) % 2 == 1) { flicker++; flickerKept += (key in kept) } }
  END { print left, motion, motionKept, flicker, flickerKept }' "$work/events.csv" "$work/boxes_flicker.aedat4.gt.csv")
read -r left motion motionKept flicker flickerKept <<< "$counts"
[ "$left" -eq "$delivered" ] || { echo "the truth has $left left-camera events, the filter reports reading $delivered"; exit 1; }
[ "$motion" -gt 10000 ] && [ "$flicker" -gt 10000 ] || { echo "too few events: $motion motion, $flicker flicker"; exit 1; }
awk -v m="$motion" -v mk="$motionKept" -v f="$flicker" -v fk="$flickerKept" \
  'BEGIN { if (mk < 0.99 * m || fk > 0.1 * f) exit 1 }' \
  || { echo "kept $motionKept of $motion motion events (>= 99 % expected), $flickerKept of $flicker flicker events (<= 10 %)"; exit 1; }
check=$(sed -n 's/^lifetime check: the edge reached the next pixel after \([0-9.]*\) lifetimes.*/\1/p' "$work/stdout.txt")
awk -v c="$check" 'BEGIN { if (c == "" || c < 0.9 || c > 1.1) exit 1 }' \
  || { echo "lifetime check median '$check', expected 1 +/- 10 %"; exit 1; }
echo "event_lifetime --filter=anti_flicker: kept $motionKept of $motion motion and $flickerKept of $flicker flicker events; lifetime check $check"
