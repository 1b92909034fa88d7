#!/usr/bin/env bash
# ctest `event_lifetime_sample`: the event_lifetime sample on the simulated moving line (75 px/s: the line is
# 0.45 m/s at 1.2 m seen with f = 200 px) writes one CSV row per event whose median lifetime is the closed-form
# 1 / 75 s = 13333 us (within 10 %), and pictures; its lifetime check (the edge reaching the next pixel after
# one lifetime) prints a median within 15 % of 1.
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
echo "event_lifetime: $rows events, median lifetime $median us (expected 13333), lifetime check $check (expected 1)"
