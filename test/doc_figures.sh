#!/usr/bin/env bash
# ctest `doc_figures`: the figures the docs quote for the real recordings (stereo, statistics, lifetime check,
# filters), the DAVIS240-pair and realistic scenes and the design choices (perf/design_figures)
# come from today's build. Each documented command runs (on ../shared/data, or on the simulator), the figure
# is taken from what it prints, formatted as the docs write it, and must appear in the doc that quotes it
# (counts exactly, percentages to the decimal the doc gives). A figure that moved fails with the command, the
# figure and the doc to update.
#
#   test/doc_figures.sh <build-dir> [shared-data-dir]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${1:?usage: doc_figures.sh <build-dir> [shared-data-dir]}
shared=${2:-$repo/../shared/data}
tum=$shared/stereo_dvs128_tum
samples=$build/samples
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# 136233 -> 136,233
thousands() { printf '%s' "$1" | sed -e ':a' -e 's/\([0-9]\)\([0-9]\{3\}\)\($\|,\)/\1,\2\3/;ta'; }
# one decimal, as the docs round
decimal() { awk -v v="$1" 'BEGIN { printf "%.1f", v }'; }

# quoted / notQuoted DOC TEXT WHAT: the verdict of one check.
quoted() { echo "ok: $1 quotes \"$2\" ($3)"; }
notQuoted() {
  echo "FAIL: $1 does not quote \"$2\": $3"
  failures=$((failures + 1))
}
# failIfAny: ends the run with the count of figures that moved, if any did.
failIfAny() {
  if [ "$failures" -gt 0 ]; then
    echo "doc_figures: $failures figures differ from what today's build prints: update the docs (or find what changed)"
    exit 1
  fi
}
# expect DOC TEXT WHAT: the doc must quote TEXT (what the command printed, formatted as the docs write it).
expect() { if grep -qF -- "$2" "$repo/$1"; then quoted "$@"; else notQuoted "$@"; fi; }

# expectProse DOC TEXT WHAT: as expect, in the doc's running text (a line break counts as a space).
expectProse() { if tr '\n' ' ' < "$repo/$1" | grep -F -- "$2" > /dev/null; then quoted "$@"; else notQuoted "$@"; fi; }

# A summary.md row's value: the text after "| LABEL ... | ".
row() { grep -m1 -F "| $2" "$1" | sed -e 's/^[^|]*|[^|]*| //' -e 's/ |$//'; }
# A summary's clock estimate as stereo.md writes it: "+3.66 +- 0.03 ms, applied".
clockEstimate() { row "$1" "right camera's clock" | sed -n 's/^\([-+0-9.]*\) ms +- \([0-9.inf]*\) ms (estimateClockOffset[^)]*): \(applied\|not applied\).*/\1 +- \2 ms, \3/p'; }

# The confidence quartiles and the share below 0.15 as doc/simulator.md's table gives them: "p25 / median / p75 | x %".
confidence() { row "$1" "confidence of the left estimates" | sed 's/ (\([0-9.]*\) % below 0.15)$/ | \1 %/'; }

stereo() {  # stereo OUTPUT-NAME ARGS...: event_stereo on a recording, its summary in $work/NAME
  local name=$1
  shift
  "$samples/event_stereo" "$@" --no-csv --output="$work/$name" > /dev/null 2> "$work/$name.err"
}

# expectPlain DOC TEXT WHAT: as expect, with the doc's bold marks ignored (grep without -q: sed would die of
# SIGPIPE, and pipefail would count that as no match).
expectPlain() { if sed 's/[*][*]//g' "$repo/$1" | grep -F -- "$2" > /dev/null; then quoted "$@"; else notQuoted "$@"; fi; }

# The DAVIS240-pair scenes (doc/simulator.md, doc/stereo.md). Their statistics as simulator.md's tables give
# them: p10 interval to 0.1 ms, median to the ms, the isolated share to the percent, no p90.
statisticsRows() {  # event_info --stats output in, the scenes' rows as simulator.md writes them out
  grep '^| scene ' | awk -F' [|] ' '{
  sub(/^[|] scene /, "", $1); sub(/ .*/, "", $1); split($7, interval, " / "); iso = $8; sub(/ %/, "", iso)
  printf "| `%s` | %s | %s | %s | %s | %s | %.1f / %.0f | %.0f %% | %s\n", $1, $2, $3, $4, $5, $6, interval[1], interval[2], iso, $9 }'
}
# The simulations run side by side; a run that fails leaves no figure, and its check fails.
"$samples/event_info" --stats --scene=boxes_pair,boxes_fast_pair,walking_pair --duration-ms=3000 > "$work/pairs.txt" &
"$build/perf/design_figures" > "$work/design.txt" &
realistic="boxes boxes_fast walking walking_near low_contrast"
for scene in boxes_pair boxes_fast_pair walking_pair $realistic; do
  stereo "$scene.own" --scene=$scene --duration-ms=3000 --set=averagingRadius=0,fillRadius=0 --right-time-offset-ms=0 &
  stereo "$scene.averaged" --scene=$scene --duration-ms=3000 --set=fillRadius=0 --right-time-offset-ms=0 &
  stereo "$scene" --scene=$scene --duration-ms=3000 &
done
wait
# With the clock estimated (the defaults' first step): the same run as the averaged one where the estimate is not
# applied.
for scene in boxes_pair boxes_fast_pair walking_pair $realistic; do
  if grep -q "right camera's clock.*: applied" "$work/$scene/summary.md"; then
    stereo "$scene.clock" --scene=$scene --duration-ms=3000 --set=fillRadius=0 &
  else
    ln -s "$work/$scene.averaged" "$work/$scene.clock"
  fi
done
wait
while IFS= read -r line; do
  expect doc/simulator.md "$line" "event_info --stats --scene=boxes_pair,boxes_fast_pair,walking_pair --duration-ms=3000"
done < <(statisticsRows < "$work/pairs.txt")
# The realistic scenes on a DVS128 (doc/simulator.md), formatted as the pairs' table.
while IFS= read -r line; do
  expect doc/simulator.md "$line" "event_info --stats --scene=boxes,boxes_fast,walking,walking_near,low_contrast,fan --sensor=DVS128"
done < <("$samples/event_info" --stats --scene=boxes,boxes_fast,walking,walking_near,low_contrast,fan --sensor=DVS128 \
           --duration-ms=1000 | statisticsRows)
while IFS= read -r line; do
  expect doc/simulator.md "$line" "event_info --stats --scene=pendulum,pendulum_patterned --sensor=DVS128 --duration-ms=3500"
done < <("$samples/event_info" --stats --scene=pendulum,pendulum_patterned --sensor=DVS128 --duration-ms=3500 | statisticsRows)
# How they match: each event's own estimate with the clocks as recorded, the averaging, the clock estimate,
# then the defaults (the filling) with their density, as simulator.md's and stereo.md's tables give them.
rate() { decimal "$(row "$1" "ground truth: matching rate" | awk '{ print $1 }')"; }
for scene in boxes_pair boxes_fast_pair walking_pair; do
  own=$(rate "$work/$scene.own/summary.md")
  misses=$(row "$work/$scene.own/summary.md" "ground truth: left signal events 1-2 px off")
  averaged=$(rate "$work/$scene.averaged/summary.md")
  clocked=$(rate "$work/$scene.clock/summary.md")
  defaults=$(rate "$work/$scene/summary.md")
  clock=$(clockEstimate "$work/$scene/summary.md")
  density=$(decimal "$(row "$work/$scene/summary.md" "ground truth: density" | awk '{ print $1 }')")
  expectPlain doc/simulator.md "| \`$scene\` | $own % | $misses | $averaged % | $clocked % | $defaults % (density $density %) |" \
    "event_stereo --scene=$scene --duration-ms=3000 --no-csv: --set=averagingRadius=0,fillRadius=0 --right-time-offset-ms=0 (matching rate, near misses), --set=fillRadius=0 --right-time-offset-ms=0, --set=fillRadius=0, defaults"
  expect doc/stereo.md "| \`$scene\` | $clocked % | $defaults % |" "the same: --set=fillRadius=0, defaults (stereo.md's filling table)"
  expectPlain doc/stereo.md "| $clock |" "event_stereo --scene=$scene --duration-ms=3000 --no-csv: clock estimate"
done
# A rectification a little off (simulator.md's table): the defaults with the right camera's focal length or
# principal point off, and as the scene is: matching rate, near misses, signed errors by third of the columns.
residuals="rightScale=0.0075 rightColumnOffset=0.5"
for scene in boxes_pair boxes_fast_pair walking_pair; do
  for setting in $residuals; do
    stereo "$scene.$setting" --scene=$scene --duration-ms=3000 --sensor-set=$setting &
  done
done
wait
residualRow() {  # residualRow SCENE SETTING-CELL SUMMARY: the table's row
  echo "| \`$1\` | $2 | $(rate "$3") % | $(row "$3" "ground truth: left signal events 1-2 px off") | $(row "$3" "ground truth: mean signed error") |"
}
for scene in boxes_pair boxes_fast_pair walking_pair; do
  expect doc/simulator.md "$(residualRow $scene "none (as the scene is)" "$work/$scene/summary.md")" \
    "event_stereo --scene=$scene --duration-ms=3000 --no-csv: the rectification table's first row"
  for setting in $residuals; do
    expect doc/simulator.md "$(residualRow $scene "\`$setting\`" "$work/$scene.$setting/summary.md")" \
      "event_stereo --scene=$scene --duration-ms=3000 --no-csv --sensor-set=$setting"
  done
done
refused=""
c=(); d=()  # per realistic scene, in order: --set=fillRadius=0 and the defaults
# The realistic scenes: the same four rates in one line of simulator.md, the last two in stereo.md's filling table,
# and what the clock estimate says.
for scene in $realistic; do
  own=$(rate "$work/$scene.own/summary.md")
  averaged=$(rate "$work/$scene.averaged/summary.md")
  c+=("$(rate "$work/$scene.clock/summary.md")")
  d+=("$(rate "$work/$scene/summary.md")")
  expectProse doc/simulator.md "\`$scene\` $own / $averaged / ${c[-1]} / ${d[-1]} %" \
    "event_stereo --scene=$scene --duration-ms=3000 --no-csv: the four settings of the pairs' table"
  clock=$(clockEstimate "$work/$scene/summary.md")
  case "$clock" in
    "+0.00 +- inf ms, not applied") refused="${refused:+$refused, }\`$scene\`" ;;
    *", not applied") expectProse doc/stereo.md "on \`$scene\` it finds ${clock%, not applied} and is not applied" "$scene: the clock estimate" ;;
    *)  # applied where the clocks agree: it must be within 0.5 ms of zero, and the doc must say so
      if awk -v e="${clock%% *}" 'BEGIN { exit !(e >= -0.5 && e <= 0.5) }'; then
        expectProse doc/stereo.md "on \`$scene\` it finds ${clock%, applied} and applies it" "$scene: the clock estimate, applied"
      else
        notQuoted doc/stereo.md "$clock" "$scene: a clock estimate more than 0.5 ms off applied on a scene whose clocks agree"
      fi ;;
  esac
done
expectProse doc/stereo.md "On the realistic scenes ($refused), whose clocks agree" "the realistic scenes whose clock estimate is refused"
expect doc/stereo.md "| \`boxes\` / \`boxes_fast\` / \`walking\` | ${c[0]} / ${c[1]} / ${c[2]} % | ${d[0]} / ${d[1]} / ${d[2]} % |" \
  "the realistic scenes: --set=fillRadius=0, defaults (stereo.md's filling table)"
expect doc/stereo.md "| \`walking_near\` / \`low_contrast\` | ${c[3]} / ${c[4]} % | ${d[3]} / ${d[4]} % |" "the same"

# The design choices' figures (perf/design_figures), as doc/benchmarks.md, doc/stereo.md and doc/lifetime.md
# quote them.
designRow() { grep -F -- "| $1" "$work/design.txt" | head -1 | awk -F' [|] ' -v f="$2" '{ v = $f; sub(/ .*/, "", v); print v }'; }
expect doc/benchmarks.md "with rejection below 0.15, $(designRow "boxes, 600 ms, minConfidence=0.15, priorTolerance=30" 3) % of the left events on" \
  "design_figures --figures=prior: with the prior, on horizontal edges"
expect doc/benchmarks.md "matched with the prior and $(designRow "boxes, 600 ms, minConfidence=0.15, priorTolerance=0" 3) % without it" \
  "design_figures --figures=prior: without it"
expect doc/stereo.md "$(designRow "boxes, 600 ms: left events" 3) % of those events get a disparity within 1 px" \
  "design_figures --figures=beyond_view"
for row in "plane, defaults" "plane, maxLifetimeCopies"; do
  expect doc/benchmarks.md "$(grep -F -- "| $row" "$work/design.txt")" "design_figures --figures=start_up: $row"
done
# The bars table: the fastest speed on its own row, the four others on one, inlierDistance 0 then the default.
bars() { grep -F -- "| $1 |" "$work/design.txt" | awk -F' [|] ' '{ v = $4; sub(/ .*/, "", v); f[NR] = $3; s[NR] = v }
  END { printf "| 0.3 ms/px | %s | %s |;| 0.6 / 1 / 3.3 / 10 ms/px | %s / %s / %s / %s | %s / %s / %s / %s |",
        f[1], s[1], f[2], f[3], f[4], f[5], s[2], s[3], s[4], s[5] }'; }
for look in "sharp, log contrast 0.5" "blurred 0.7 px, log contrast 1.0"; do
  IFS=';' read -r fastest others <<< "$(bars "$look")"
  expectPlain doc/lifetime.md "$fastest" "design_figures --figures=bars: $look at 0.3 ms/px"
  expectPlain doc/lifetime.md "$others" "design_figures --figures=bars: $look at 0.6-10 ms/px"
done
halfFiring() { grep -F -- "| half-firing" "$work/design.txt" | sed -n "$1p" | sed -n "s/.*$2: \([0-9.]*\) .*/\1/p"; }
expect doc/lifetime.md "median $(halfFiring 1 "timeWindow 100 ms") times the closed form" \
  "design_figures --figures=bars: half-firing bars at 0.3 ms/px, 100 ms window"
expect doc/lifetime.md "and $(halfFiring 2 "timeWindow 100 ms") times at 1 ms/px" "design_figures --figures=bars: half-firing bars at 1 ms/px, 100 ms window"
expect doc/lifetime.md "$(halfFiring 1 "8 px of travel") and $(halfFiring 2 "8 px of travel") times the closed form" \
  "design_figures --figures=bars: half-firing bars, 8 px of travel"
# The slowing pendulum's table (design_figures --figures=slowing), row by row.
for row in "\`pendulum\`, as built" "\`pendulum\`, as TUM" "\`pendulum_patterned\`, as built" "\`pendulum_patterned\`, as TUM"; do
  expect doc/lifetime.md "$(grep -F -- "| $row" "$work/design.txt")" "design_figures --figures=slowing: $row"
done
# The swinging ball's tracked lifetimes against the check (perf/ball_motion_check, doc/benchmarks.md): every row
# it prints, the TUM pendulum's when present.
ballArgs=()
if [ -d "$tum" ]; then ballArgs=(--recording="$tum/pendulum_left_30cm_2.tsv.txt"); fi
while IFS= read -r row; do
  expect doc/benchmarks.md "$row" "ball_motion_check:$(cut -d'|' -f2,3 <<< "$row")"
done < <("$build/perf/ball_motion_check" "${ballArgs[@]}" | grep -E '^[|] (simulated|TUM)')
# What row bands can give at most (perf/row_band_ceiling, doc/benchmarks.md): every row of both sensors' runs.
for sensor in DAVIS240 DAVIS346; do
  "$build/perf/row_band_ceiling" --scenes=boxes,boxes_fast,walking,walking_near,low_contrast --sensor=$sensor \
    --duration-ms=1000 --bands=2,4,7,10,16 > "$work/ceiling_$sensor.txt" 2> /dev/null &
done
wait
ceilingRows=$(grep -hE '^[|] [a-z_]+ [(]sim' "$work"/ceiling_DAVIS*.txt || true)
if [ "$(grep -c . <<< "$ceilingRows")" -ne 10 ]; then
  notQuoted doc/benchmarks.md "10 rows" "row_band_ceiling printed $(grep -c . <<< "$ceilingRows") rows of the scenes"
fi
while IFS= read -r row; do
  if [ -n "$row" ]; then expect doc/benchmarks.md "$row" "row_band_ceiling:$(cut -d'|' -f2 <<< "$row")"; fi
done <<< "$ceilingRows"

if [ ! -d "$tum" ]; then
  # The real recordings' figures need them; the simulated ones above are checked (a failure there is one).
  failIfAny
  echo "SKIP: $tum not found: the real recordings' figures are not checked"
  exit 0
fi

# Fan, the right way round: its share at 8 px, its row estimate (doc/stereo.md); the median confidence
# (README, a regression pin's today figure).
stereo fan --input="$tum/Fan_disp8.dat" --sensor=DVS128 --left-camera-value=1
share=$(row "$work/fan/summary.md" "dominant disparity" | sed -n 's/^8 px (\([0-9.]*\) %.*/\1/p')
expect doc/stereo.md "$(decimal "$share") % of its estimates at its 8 px" "event_stereo --input=Fan_disp8.dat --sensor=DVS128 --left-camera-value=1: dominant disparity"
sides=$(row "$work/fan/summary.md" "row alignment" | sed -n 's/.*up to \([0-9.]*\) px at the sides.*/\1/p')
expect doc/stereo.md "up to $sides px at the sides" "the same run: row alignment"
fanMedian=$(row "$work/fan/summary.md" "confidence of the left estimates" | awk -F' / ' '{ print $2 }')

# movingPersons both ways round (doc/stereo.md).
stereo mp --input="$tum/movingPersons.dat" --sensor=DVS128 --one-based
with=$(row "$work/mp/summary.md" "events with a disparity" | awk '{ print $1 }')
at13=$(row "$work/mp/summary.md" "dominant disparity" | sed -n 's/^13 px (\([0-9.]*\) %.*/\1/p')
expect doc/stereo.md "against $(decimal "$with") % the right way round, $(decimal "$at13") % of those at 13 px" \
  "event_stereo --input=movingPersons.dat --sensor=DVS128 --one-based"
stereo mp_swapped --input="$tum/movingPersons.dat" --sensor=DVS128 --one-based --left-camera-value=1
with=$(row "$work/mp_swapped/summary.md" "events with a disparity" | awk '{ print $1 }')
expect doc/stereo.md "movingPersons: $(decimal "$with") % of its events get a disparity" \
  "event_stereo --input=movingPersons.dat --sensor=DVS128 --one-based --left-camera-value=1"
mpMedian=$(row "$work/mp/summary.md" "confidence of the left estimates" | awk -F' / ' '{ print $2 }')
expect README.md "today $fanMedian and $mpMedian" "event_stereo on Fan and movingPersons: median confidence"

# The pendulum: every event accounted for (README).
stereo pendulum --input="$tum/pendulum_left_30cm_2.tsv.txt" --sensor=DVS128 --max-disparity=50
processed=$(row "$work/pendulum/summary.md" "events |" | awk '{ print $1 }')
outside=$(row "$work/pendulum/summary.md" "input events outside the sensor" | awk '{ print $1 }')
expect README.md "every one of the pendulum's $(thousands $((processed + outside))) events ($(thousands "$outside") lie outside" \
  "event_stereo on pendulum_left_30cm_2.tsv.txt: events and events outside the sensor"

# How clear-cut the matches are on each TUM recording (doc/simulator.md, the commands above it).
stereo faraway --input="$tum/movingPersonFaraway.dat" --sensor=DVS128 --one-based
for pair in "fan:Fan" "mp:movingPersons" "faraway:movingPersonFaraway" "pendulum:pendulum"; do
  expect doc/simulator.md "| TUM ${pair#*:} | $(confidence "$work/${pair%%:*}/summary.md") |" "event_stereo on ${pair#*:}: confidence quartiles"
done

# How the TUM recordings' streams look (doc/simulator.md's statistics table, its commands): the left camera's
# figures and the right camera's event count over the left one's, as event_info --stats' table gives them.
statsRow() {  # statsRow NAME ARGS...: "| TUM NAME (DVS128) | kev/s | right / left | ON | ... |"
  local name=$1
  shift
  "$samples/event_info" --stats --sensor=DVS128 "$@" > "$work/stats.txt"
  awk -F' [|] ' -v name="$name" '
    $2 == "left" { left = $3 " | RATIO | " $5 " | " $6 " | " $7 " | " $8 " | " $9 }
    $2 == "right" { ratio = $4 }
    END { sub(/ [|]$/, "", left); sub("RATIO", ratio, left); print "| TUM " name " (DVS128) | " left " |" }' \
    <(grep '^| /' "$work/stats.txt")
}
expect doc/simulator.md "$(statsRow Fan --left-camera-value=1 "$tum/Fan_disp8.dat")" "event_info --stats on Fan_disp8.dat"
expect doc/simulator.md "$(statsRow movingPersons --one-based "$tum/movingPersons.dat")" "event_info --stats on movingPersons.dat"
expect doc/simulator.md "$(statsRow movingPersonFaraway --one-based "$tum/movingPersonFaraway.dat")" \
  "event_info --stats on movingPersonFaraway.dat"
expect doc/simulator.md "$(statsRow pendulum "$tum/pendulum_left_30cm_2.tsv.txt")" "event_info --stats on pendulum_left_30cm_2.tsv.txt"

for pair in "aestream_davis346.aedat4:DAVIS346 sample (aestream, mono)" "tonic_sample_dvxplorer.aedat4:DVXplorer sample (tonic, mono)"; do
  "$samples/event_info" --stats "$shared/format_samples/${pair%%:*}" > "$work/stats.txt"
  row=$(grep '^| /' "$work/stats.txt" | awk -F' [|] ' -v name="${pair#*:}" \
    '{ line = "| " name " | " $3 " | | " $5 " | " $6 " | " $7 " | " $8 " | " $9; sub(/ [|]$/, "", line); print line " |" }')
  expect doc/simulator.md "$row" "event_info --stats ${pair%%:*}"
done

# The trigger events of the evt3 bags (doc/reading_recordings.md): event_info's count by kind.
triggers() { "$samples/event_info" "$shared/format_samples/$1" | sed -n 's/^  triggers:  \([0-9]*\) (falling \([0-9]*\), rising \([0-9]*\))$/\1 \2 \3/p'; }
read -r total falling rising < <(triggers ecpy_test_events_1_ros1.bag)
expect doc/reading_recordings.md "holds $(thousands "$total")" "event_info ecpy_test_events_1_ros1.bag: triggers"
expect doc/reading_recordings.md "$(thousands "$rising") rising, $(thousands "$falling") falling edges" \
  "event_info ecpy_test_events_1_ros1.bag: triggers by kind"
read -r total falling rising < <(triggers ecpy_legacy_eventarray_ros2)
expect doc/reading_recordings.md "\`test_events_ros2_1\` $total" "event_info ecpy_legacy_eventarray_ros2: triggers"
expect doc/reading_recordings.md "($rising and $falling)" "event_info ecpy_legacy_eventarray_ros2: triggers by kind"

# The hot-pixel filter on each TUM recording (doc/filters.md, its command), at relativeRate 10 and 5: the
# events removed, as the table writes them ("0", or "N (x %)", two decimals below 0.1 %).
removedText() {  # removedText KEPT TOTAL
  local removed=$(($2 - $1))
  if [ "$removed" = 0 ]; then printf '0'; return; fi
  printf '%s (%s %%)' "$(thousands "$removed")" \
    "$(awk -v r=$removed -v t="$2" 'BEGIN { p = 100 * r / t; printf (p < 0.1 ? "%.2f" : "%.1f"), p }')"
}
for pair in "Fan_disp8.dat:two fans (9.8 s)" "movingPersons.dat:two people walking (10.1 s):--one-based" \
            "movingPersonFaraway.dat:a person far away (10.0 s):--one-based" "pendulum_left_30cm_2.tsv.txt:a pendulum (13.7 s)"; do
  IFS=: read -r file label extra <<< "$pair"
  line="| $label |"
  for rate in 10 5; do
    "$samples/event_player" "$tum/$file" --sensor=DVS128 $extra --filter=hot_pixels --filter-set=relativeRate=$rate \
      --output="$work/hot" > /dev/null 2> "$work/hot.err"
    read -r kept total < <(tr '\r' '\n' < "$work/hot.err" | sed -n 's/^hot_pixels kept \([0-9]*\) of \([0-9]*\) events$/\1 \2/p')
    [ "$rate" = 10 ] && line="$line $(thousands "$total") |"
    line="$line $(removedText "$kept" "$total") |"
  done
  expect doc/filters.md "$line" "event_player $file --sensor=DVS128 $extra --filter=hot_pixels, relativeRate 10 and 5"
done

# The lifetime check on every real recording (doc/lifetime.md's table, its commands): "median (quartiles)" for
# inlierDistance=0 and the defaults, two decimals (one from 10 on), the doc's bold marks ignored.
arrival() {  # arrival FILE ARGS...: event_lifetime's check line as the table writes it
  local file=$1
  shift
  "$samples/event_lifetime" "$file" "$@" --output="$work/lifetime" 2> /dev/null \
    | sed -n 's/^lifetime check: the edge reached the next pixel after \([0-9.]*\) lifetimes (median; quartiles \([0-9.]*\) \/ \([0-9.]*\)) over.*/\1 \2 \3/p' \
    | awk '{ for (i = 1; i <= 3; i++) v[i] = sprintf($i < 10 ? "%.2f" : "%.1f", $i); print v[1] " (" v[2] " / " v[3] ")" }'
}
# Each recording in both tables: the check at inlierDistance=0 and at the defaults, and in the quality table
# the lifetimes kept at quality >= 0.75 with the check over them. Entries: FILE:OPTIONS:check-table label:
# quality-table label (none: the recording is in the check table only).
for entry in "format_samples/aestream_davis346.aedat4::DAVIS346 sample (aestream, 346 x 260):DAVIS346 sample (aestream)" \
             "stereo_dvs128_tum/Fan_disp8.dat:--sensor=DVS128:TUM Fan (DVS128, \`--sensor=DVS128\`):TUM Fan" \
             "stereo_dvs128_tum/pendulum_left_30cm_2.tsv.txt:--sensor=DVS128:TUM pendulum (DVS128):TUM pendulum" \
             "stereo_dvs128_tum/movingPersons.dat:--sensor=DVS128 --one-based:TUM movingPersons (DVS128, \`--one-based\`):TUM movingPersons" \
             "format_samples/tonic_sample_dvxplorer.aedat4::DVXplorer sample (tonic):DVXplorer sample (tonic)" \
             "format_samples/ecpy_test_events_2_mcap::DAVIS346 ROS 2 bag, MCAP (event_camera_py):DAVIS346 ROS 2 bag, MCAP" \
             "format_samples/ecpy_test_events_1_ros1.bag::640 x 480 ROS 1 bag, EVT 3.0 packets (event_camera_py; its legacy \`EventArray\` twin reads the same):640 x 480 ROS 1 bag" \
             "format_samples/evt2_sample.raw::Prophesee EVT 2.0 sample (Gen3, 640 x 480):Prophesee EVT 2.0 sample" \
             "format_samples/evt3_sample.raw::Prophesee EVT 3.0 sample (Gen4, 1280 x 720):Prophesee EVT 3.0 sample" \
             "format_samples/tonic_sample_ncars.dat:--sensor=304x240:N-CARS sample (ATIS, \`--sensor=304x240\`):" \
             "format_samples/ecpy_legacy_eventarray_ros2::640 x 480 ROS 2 bag, legacy \`EventArray\`:" \
             "format_samples/ros2_libcaer_rollover::libcaer ROS 2 bag (640 x 480):"; do
  IFS=: read -r file extra checkLabel qualityLabel <<< "$entry"
  expectPlain doc/lifetime.md "| $checkLabel | $(arrival "$shared/$file" $extra --set=inlierDistance=0) | $(arrival "$shared/$file" $extra) |" \
    "event_lifetime $file $extra, inlierDistance=0 and the defaults: the lifetime check"
  [ -n "$qualityLabel" ] || continue
  kept=$("$samples/event_lifetime" "$shared/$file" $extra --min-quality=0.75 --output="$work/lifetime" 2> /dev/null \
    | sed -n 's/^quality >= 0.75: [0-9]* of [0-9]* lifetimes (\([0-9.]*\) %)$/\1/p')
  expect doc/lifetime.md "| $qualityLabel | $kept % | $(arrival "$shared/$file" $extra --min-quality=0.75) |" \
    "event_lifetime $file $extra --min-quality=0.75: lifetimes kept, the lifetime check"
done
# The legacy ROS 1 bag holds the same recording as the ROS 1 bag of the table (its row says so).
legacyRos1="$shared/format_samples/ecpy_legacy_eventarray_ros1.bag"
expectPlain doc/lifetime.md "twin reads the same) | $(arrival "$legacyRos1" --set=inlierDistance=0) | $(arrival "$legacyRos1") |" \
  "event_lifetime ecpy_legacy_eventarray_ros1.bag, inlierDistance=0 and the defaults: the lifetime check"
# The check before and after the anti-flicker filter (doc/lifetime.md, "A flickering light"): the events kept and
# the check over them.
for entry in "--scene=boxes_flicker:simulated \`boxes_flicker\` (\`--scene=boxes_flicker\`: \`boxes\` lit at 100 Hz)" \
             "$shared/format_samples/aestream_davis346.aedat4:DAVIS346 sample (aestream)"; do
  IFS=: read -r source label <<< "$entry"
  kept=$("$samples/event_lifetime" "$source" --filter=anti_flicker --output="$work/lifetime" 2> /dev/null \
    | sed -n 's/^filter anti_flicker: kept [0-9]* of [0-9]* events (\([0-9.]*\) %)$/\1/p')
  expect doc/lifetime.md "| $label | $(arrival "$source") | $kept % | $(arrival "$source" --filter=anti_flicker) |" \
    "event_lifetime $source, without and with --filter=anti_flicker: the lifetime check, the events kept"
done
# The same check on the realistic scenes simulated on a DVS128 (the table's last rows).
for entry in "walking:simulated \`walking\` on a DVS128 (\`--scene=walking --sensor=DVS128\`)" \
             "boxes:simulated \`boxes\` on a DVS128" "walking_near:simulated \`walking_near\` on a DVS128" \
             "fan:simulated \`fan\` on a DVS128" "pendulum:simulated \`pendulum\` on a DVS128" \
             "pendulum_patterned:simulated \`pendulum_patterned\` on a DVS128"; do
  IFS=: read -r scene label <<< "$entry"
  expectPlain doc/lifetime.md "| $label | $(arrival --scene=$scene --sensor=DVS128 --set=inlierDistance=0) | $(arrival --scene=$scene --sensor=DVS128) |" \
    "event_lifetime --scene=$scene --sensor=DVS128, inlierDistance=0 and the defaults: the lifetime check"
done
# A fan that fires as sparsely as TUM Fan (doc/lifetime.md): the share of the left camera's events with a lifetime
# and our check, perfect lifetimes' check ("as built"), and our median error against the truth.
sparseFanSetting=(--sensor=DVS128 --duration-ms=3500 --sensor-set=blurSigmaPx=0.6)
sparseFan=(--scene=fan "${sparseFanSetting[@]}")
"$build/perf/lifetime_check_bias" --scenes=fan "${sparseFanSetting[@]}" --effects=false > "$work/sparse_fan_bias.txt" \
  2> /dev/null &
"$samples/event_lifetime" "${sparseFan[@]}" --output="$work/sparse_fan" > "$work/sparse_fan.txt" 2> /dev/null
fanShare=$(sed -n 's/^\([0-9]*\) events of camera 0: \([0-9]*\) fitted, \([0-9]*\) predicted.*/\1 \2 \3/p' "$work/sparse_fan.txt" \
  | awk '{ printf "%.0f", 100 * ($2 + $3) / $1 }')
expectProse doc/lifetime.md "$fanShare % of its left camera's events get a lifetime" "event_lifetime ${sparseFan[*]}: events with a lifetime"
expectProse doc/lifetime.md "on TUM Fan, $(arrival "${sparseFan[@]}")." "event_lifetime ${sparseFan[*]}: the lifetime check"
fanError=$("$samples/event_evaluate" "${sparseFan[@]}" --method=lifetime --output="$work/sparse_fan_eval" 2> /dev/null \
  | tail -1 | sed -n 's/^lifetime median relative error \([0-9.]*\) %.*/\1/p')
expectProse doc/lifetime.md "ours are $(decimal "$fanError") % off them" "event_evaluate ${sparseFan[*]} --method=lifetime: median error"
wait
fanPerfect=$(grep -F '| as built |' "$work/sparse_fan_bias.txt" | awk -F' [|] ' '{ print $4 }' | sed 's/ |$//')
expectProse doc/lifetime.md "true lifetimes check at $fanPerfect there" "lifetime_check_bias --scenes=fan ${sparseFanSetting[*]} --effects=false"
# The simulator's scenes against their true lifetimes at quality 0, 0.75 and 0.8 (the same table's first part):
# "median % (events)".
qualityCell() {  # qualityCell SCENE Q
  "$samples/event_evaluate" --scene="$1" --duration-ms=1000 --method=lifetime --min-quality="$2" \
    --output="$work/quality" 2> /dev/null | tail -1 | sed -n 's/^lifetime median relative error \([0-9.]*\) %, \([0-9]*\) of [0-9]* events with a lifetime.*/\1 \2/p'
}
for scene in boxes_pair walking_pair cluttered walking; do
  line=""
  for q in 0 0.75 0.8; do
    read -r error events < <(qualityCell $scene $q)
    line="$line | $(decimal "$error") % ($(thousands "$events"))"
  done
  expectProse doc/lifetime.md "$line |" "event_evaluate --scene=$scene --duration-ms=1000 --method=lifetime --min-quality=0 / 0.75 / 0.8"
done

# Which TUM files count pixels from 1 (doc/reading_recordings.md).
"$samples/event_info" "$tum/movingPersons.dat" "$tum/movingPersonFaraway.dat" "$tum/Fan_disp8.dat" > "$work/info.txt"
ranges=$(sed -n 's/^  pixels:    //p' "$work/info.txt" | tr '\n' ';')
if [ "$ranges" = "x 1..128, y 1..128;x 1..128, y 1..128;x 0..127, y 0..127;" ]; then
  expect doc/reading_recordings.md "movingPersonFaraway count from 1, x and y 1..128" "event_info: pixels"
else
  echo "FAIL: event_info gives the TUM files' pixels as $ranges: doc/reading_recordings.md says otherwise"
  failures=$((failures + 1))
fi

failIfAny
echo "doc_figures: every checked figure is today's"
