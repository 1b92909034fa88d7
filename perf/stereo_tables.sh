#!/usr/bin/env bash
# The accuracy tables of doc/benchmarks.md's stereo sections that event_evaluate and event_stereo give, printed
# as the page writes them: the realistic scenes by method (and where COUPLED's other events go), over six
# seeds, each parameter, lifetimes and noise by parameter, the idealised scenes, the pendulum, and the real TUM
# pairs. Each run is the command above its table on the page.
#
#   perf/stereo_tables.sh [--build=DIR] [--shared=DIR] [--set=LIST] [--jobs=N] [--tables=NAME,...] [--work=DIR]
#
# --set=LIST adds LIST to every run's matcher settings (after the table's own), to see every table under a
#   setting before making it a default; the rows keep their labels.
# --tables: realistic, seeds, parameters, lifetimes, idealised, pendulum, tum (default: all). About 30 minutes
#   for all of them on two cores (--jobs=2, the default); the TUM pairs are read from --shared (default
#   ../shared/data) and skipped when absent.
# --work=DIR keeps the runs' outputs there (a temporary folder otherwise; one folder per --set) and skips the runs
#   that succeeded there, so that an interrupted run resumes and a failed one runs again.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=$repo/build
shared=$repo/../shared/data
extra=""
jobs=2
tables="realistic,seeds,parameters,lifetimes,idealised,pendulum,tum"
work=""
for arg in "$@"; do
  case "$arg" in
    --build=*) build=${arg#--build=} ;;
    --shared=*) shared=${arg#--shared=} ;;
    --set=*) extra=${arg#--set=} ;;
    --jobs=*) jobs=${arg#--jobs=} ;;
    --tables=*) tables=${arg#--tables=} ;;
    --work=*) work=${arg#--work=} ;;
    *) echo "usage: $0 [--build=DIR] [--shared=DIR] [--set=LIST] [--jobs=N] [--tables=NAME,...] [--work=DIR]" >&2; exit 2 ;;
  esac
done
samples=$build/samples
tum=$shared/stereo_dvs128_tum
if [ -n "$work" ]; then
  mkdir -p "$work"
  work=$(cd "$work" && pwd)
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
wanted() { [[ ",$tables," == *",$1,"* ]]; }

realistic="boxes boxes_fast walking walking_near low_contrast"
# The rows of "Each parameter on the realistic scenes", in the page's order. Every row but "fillRadius=0" and
# the defaults is each event's own estimate: fillRadius=0 is added to its list.
parameterRows=(
  "averagingRadius=0,costWindow=9,aggregationWindow=17,priorTolerance=0,lookAhead=0,minConfidence=0.15,noiseActiveTime=0,recencyWeight=0,lifetimeCopyConfidence=0"
  "averagingRadius=0,costWindow=9,priorTolerance=0,lookAhead=0,minConfidence=0.15,noiseActiveTime=0,recencyWeight=0,lifetimeCopyConfidence=0"
  "averagingRadius=0,costWindow=9,lookAhead=0,minConfidence=0.15,noiseActiveTime=0,recencyWeight=0,lifetimeCopyConfidence=0"
  "averagingRadius=0,costWindow=9,minConfidence=0.15,noiseActiveTime=0,recencyWeight=0,lifetimeCopyConfidence=0"
  "averagingRadius=0,minConfidence=0.15,noiseActiveTime=0,recencyWeight=0,lifetimeCopyConfidence=0"
  "averagingRadius=0,noiseActiveTime=0,recencyWeight=0,lifetimeCopyConfidence=0"
  "averagingRadius=0,recencyWeight=0,lifetimeCopyConfidence=0"
  "averagingRadius=0,lifetimeCopyConfidence=0"
  "averagingRadius=0"
  "fillRadius=0"
  "defaults"
  "averagingRadius=0,lifetimeCopyConfidence=0.2" "averagingRadius=0,lifetimeCopyConfidence=0.4"
  "averagingRadius=0,noiseActiveTime=0" "averagingRadius=0,noiseActiveTime=10000" "averagingRadius=0,noiseActiveTime=50000"
  "averagingRadius=0,maxLifetimeCopies=255"
  "averagingRadius=0,costWindow=9" "averagingRadius=0,costWindow=13" "averagingRadius=0,costWindow=21" "averagingRadius=0,costWindow=25"
  "averagingRadius=0,lifetimeWindow=17"
  "averagingRadius=0,priorTolerance=0" "averagingRadius=0,priorTolerance=100"
  "averagingRadius=0,minConfidence=0.05" "averagingRadius=0,minConfidence=0.15" "averagingRadius=0,minConfidence=0.25"
  "averagingRadius=0,matchedLifetimeConfidence=0" "averagingRadius=0,matchedLifetimeConfidence=0.3"
  "averagingRadius=0,maxVectorLength=5"
  "averagingRadius=0,uniquenessRatio=5" "averagingRadius=0,uniquenessRatio=0"
  "averagingRadius=0,lookAhead=0" "averagingRadius=0,lookAhead=2000" "averagingRadius=0,lookAhead=5000"
  "averagingRadius=0,recencyWeight=0" "averagingRadius=0,recencyWeight=30"
  "averagingRadius=0,recencyTime=5000" "averagingRadius=0,recencyTime=20000"
)
# The TUM table's settings, in the page's order ("" is the defaults).
tumRows=(
  "" "fillRadius=0" "averagingRadius=0,fillRadius=0" "recencyWeight=0" "lifetimeCopyConfidence=0"
  "maxLifetimeCopies=255,lifetimeCopyConfidence=0" "lookAhead=0" "priorTolerance=0" "minConfidence=0.15"
  "matchedLifetimeConfidence=0" "costWindow=9" "costRowStep=1" "costRowStep=3" "noiseActiveTime=0"
  "costWindow=9,aggregationWindow=17,priorTolerance=0,lookAhead=0,minConfidence=0.15,noiseActiveTime=0,recencyWeight=0,lifetimeCopyConfidence=0,averagingRadius=0,fillRadius=0"
)

# withExtra LIST: the --set option for LIST followed by --set's list (nothing when both are empty).
withExtra() {
  local list=$1
  [ -n "$extra" ] && list=${list:+$list,}$extra
  [ -n "$list" ] && printf -- '--set=%s' "$list"
  return 0
}
# The jobs: one line each, "OUTPUT-DIR<TAB>COMMAND ARGS...", run $jobs at a time.
jobList=$work/jobs.txt
: > "$jobList"
job() {  # job NAME PROGRAM ARGS...: run unless --work holds its output already
  local name=$1
  shift
  [ -f "$work/$name.done" ] && return 0
  printf '%s\t%s\n' "$work/$name" "$*" >> "$jobList"
}
evaluate() {  # evaluate NAME SCENE METHOD LIST [MORE ARGS]: event_evaluate, 1 s unless MORE says otherwise
  local name=$1 scene=$2 method=$3 list=$4
  shift 4
  local set=""
  [ "$method" != sgbm ] && set=$(withExtra "$list")
  job "$name" "$samples/event_evaluate" --scene="$scene" --duration-ms=1000 --method="$method" ${set:+"$set"} "$@"
}
key() { printf '%s' "$1" | md5sum | cut -c1-12; }  # a directory name for a --set list

# The lifetimes table's first row is the realistic table's COUPLED runs.
if wanted realistic || wanted lifetimes; then
  for scene in $realistic; do
    for m in coupled decoupled fixed sgbm; do evaluate "real.$scene.$m" "$scene" "$m" ""; done
  done
fi
if wanted lifetimes; then
  for scene in $realistic; do
    evaluate "life.$scene.mlc0" "$scene" coupled "matchedLifetimeConfidence=0"
    evaluate "life.$scene.copies" "$scene" coupled "maxLifetimeCopies=255"
  done
fi
if wanted seeds; then
  for scene in $realistic; do
    for seed in 0 1 2 3 4 5; do
      for m in coupled decoupled fixed; do
        evaluate "seed.$scene.$m.$seed" "$scene" "$m" "averagingRadius=0,fillRadius=0" --sensor-set=seed=$seed
      done
      evaluate "seed.$scene.sgbm.$seed" "$scene" sgbm "" --sensor-set=seed=$seed
      evaluate "seed.$scene.copy0.$seed" "$scene" coupled "averagingRadius=0,fillRadius=0,lifetimeCopyConfidence=0" --sensor-set=seed=$seed
      evaluate "seed.$scene.recency0.$seed" "$scene" coupled "averagingRadius=0,fillRadius=0,recencyWeight=0" --sensor-set=seed=$seed
    done
  done
fi
parameterList() {  # the --set list of a parameter row
  case "$1" in
    defaults) echo "" ;;
    fillRadius=0) echo "fillRadius=0" ;;
    *) echo "$1,fillRadius=0" ;;
  esac
}
if wanted parameters; then
  for row in "${parameterRows[@]}"; do
    for scene in $realistic; do
      evaluate "param.$scene.$(key "$row")" "$scene" coupled "$(parameterList "$row")"
    done
  done
fi
if wanted idealised; then
  for scene in plane two_planes cluttered; do
    evaluate "ideal.$scene" "$scene" coupled ""
    evaluate "ideal.$scene.published" "$scene" coupled "maxLifetimeCopies=255,lifetimeCopyConfidence=0" --duration-ms=600
  done
fi
pendulumRuns=("coupled:" "coupled:maxLifetime=10000" "coupled:activeDistance=1" "coupled:averagingRadius=0,fillRadius=0"
              "decoupled:" "fixed:" "sgbm:")
if wanted pendulum; then
  for run in "${pendulumRuns[@]}"; do
    m=${run%%:*}
    list=${run#*:}
    set=""
    [ "$m" != sgbm ] && set=$(withExtra "$list")
    job "pend.$m.$(key "$list")" "$samples/event_stereo" --scene=pendulum --sensor=DVS128 --duration-ms=3500 \
      --max-disparity=50 --mode="$m" --threads=1 --no-csv ${set:+"$set"}
  done
fi
tumFiles=("fan:Fan_disp8.dat:--left-camera-value=1" "mp:movingPersons.dat:--one-based" "pendulum:pendulum_left_30cm_2.tsv.txt:--max-disparity=50")
if wanted tum; then
  if [ -d "$tum" ]; then
    for row in "${tumRows[@]}"; do
      for f in "${tumFiles[@]}"; do
        IFS=: read -r name file options <<< "$f"
        set=$(withExtra "$row")
        job "tum.$name.$(key "$row")" "$samples/event_stereo" --input="$tum/$file" --sensor=DVS128 "$options" --threads=1 ${set:+"$set"}
      done
    done
  else
    echo "SKIP: $tum not found: no TUM table" >&2
  fi
fi

total=$(($(wc -l < "$jobList")))
before=$(find "$work" -maxdepth 1 -name '*.done' | wc -l)
echo "stereo_tables: $total runs, $jobs at a time${extra:+, every one with --set=$extra}" >&2
export work total before
# Each job in its own output folder; a failed run leaves no report, and its cells read "failed".
tr '\t' '\n' < "$jobList" | xargs -r -d '\n' -n 2 -P "$jobs" sh -c 'cmd=$1; mkdir -p "$0"; if $cmd --output="$0" > "$0.log" 2>&1; then touch "$0.done"; else echo "FAILED: $cmd ($0.log)" >&2; fi; printf "\r%s of %s runs done" "$(($(find "$work" -maxdepth 1 -name "*.done" | wc -l) - before))" "$total" >&2'
echo >&2

# field FILE LABEL: the value cell of the row of a report.md or summary.md whose label starts with LABEL.
field() {
  local f
  for f in "$1/report.md" "$1/summary.md"; do
    [ -f "$f" ] && awk -v label="| $2" 'index($0, label) == 1 { sub(/^[|][^|]*[|] /, ""); sub(/ [|]$/, ""); print; exit }' "$f"
  done
  return 0
}
decimal() { awk -v v="$1" 'BEGIN { if (v == "") print "failed"; else printf "%.1f", v }'; }
first() { awk '{ print $1 }'; }
density() { decimal "$(field "$1" "disparity density" | first)"; }
within() { decimal "$(field "$1" "estimated events within 1 px" | first)"; }
rawRate() { field "$1" "matching rate (left signal events within 1 px of the truth" | first; }
rate() { decimal "$(rawRate "$1")"; }
lifetimeError() { local v; v=$(field "$1" "lifetime median relative error" | first); if [ -z "$v" ]; then echo none; else echo "$(decimal "$v") %"; fi; }

if wanted realistic; then
  echo
  echo "| scene | method | density | within 1 px | matching rate | precision at 50 / 75 % density | lifetime error |"
  echo "|---|---|---|---|---|---|---|"
  for scene in $realistic; do
    for m in coupled decoupled fixed sgbm; do
      d=$work/real.$scene.$m
      precision=$(field "$d" "precision (within 1 px) of the most confident")
      case "$precision" in n/a*) precision="no confidence" ;; esac
      echo "| $scene | $m | $(density "$d") % | $(within "$d") % | $(rate "$d") % | $precision | $(lifetimeError "$d") |"
    done
  done
  echo
  echo "| scene | more than 1 px off | no candidate within the look-ahead |"
  echo "|---|---|---|"
  for scene in boxes boxes_fast; do
    read -r off _ _ _ none _ < <(field "$work/real.$scene.coupled" "left signal events more than 1 px off")
    echo "| $scene | $(decimal "$off") % | $(decimal "$none") % |"
  done
fi

if wanted seeds; then
  # meanRange PREFIX [mean]: "mean % (least-most)" of the six seeds' matching rates, or the mean alone.
  meanRange() {
    for seed in 0 1 2 3 4 5; do rawRate "$work/$1.$seed"; done | awk -v only="${2:-}" '
      { s += $1; if (NR == 1 || $1 < lo) lo = $1; if (NR == 1 || $1 > hi) hi = $1 }
      END { if (NR != 6) printf "failed"; else if (only != "") printf "%.1f %%", s / NR; else printf "%.1f %% (%.1f-%.1f)", s / NR, lo, hi }'
  }
  echo
  echo "| scene | COUPLED | DECOUPLED | FIXED | SGBM | COUPLED, \`lifetimeCopyConfidence=0\` | COUPLED, \`recencyWeight=0\` |"
  echo "|---|---|---|---|---|---|---|"
  for scene in $realistic; do
    echo "| \`$scene\` | $(meanRange seed.$scene.coupled) | $(meanRange seed.$scene.decoupled) | $(meanRange seed.$scene.fixed) | $(meanRange seed.$scene.sgbm) | $(meanRange seed.$scene.copy0 mean) | $(meanRange seed.$scene.recency0 mean) |"
  done
fi

if wanted parameters; then
  echo
  echo "| \`--set=\` | boxes | boxes_fast | walking | walking_near | low_contrast |"
  echo "|---|---|---|---|---|---|"
  for row in "${parameterRows[@]}"; do
    if [ "$row" = defaults ]; then line="| **defaults** |"; else line="| \`$row\` |"; fi
    for scene in $realistic; do
      d=$work/param.$scene.$(key "$row")
      line="$line $(rate "$d") ($(density "$d") / $(within "$d")) |"
    done
    echo "$line"
  done
fi

if wanted lifetimes; then
  recall() { field "$1" "noise precision / recall" | awk -F' / ' '{ v = $2; sub(/ %.*/, "", v); if (v == "") print "failed"; else printf "%.0f %%", v }'; }
  echo
  echo "| \`--set=\` | boxes | boxes_fast | walking | walking_near | low_contrast |"
  echo "|---|---|---|---|---|---|"
  line="| defaults: noise recall |"; for s in $realistic; do line="$line $(recall "$work/real.$s.coupled") |"; done; echo "$line"
  line="| \`matchedLifetimeConfidence=0\`: noise recall |"; for s in $realistic; do line="$line $(recall "$work/life.$s.mlc0") |"; done; echo "$line"
  line="| \`matchedLifetimeConfidence=0\`: lifetime error |"; for s in $realistic; do line="$line $(lifetimeError "$work/life.$s.mlc0") |"; done; echo "$line"
  line="| \`maxLifetimeCopies=255\`: lifetime error |"; for s in $realistic; do line="$line $(lifetimeError "$work/life.$s.copies") |"; done; echo "$line"
fi

if wanted idealised; then
  # The share of the events; below 100 but within 0.05 of it, two decimals rounded down (never "100" for a share
  # that misses some).
  share() { awk -v v="$1" 'BEGIN { if (v == "") print "failed"; else if (v < 100 && v >= 99.95) printf "%.2f", int(v * 100) / 100; else printf "%.1f", v }'; }
  echo
  echo "| scene | density | within 1 px | lifetime error | lifetime error as published (600 ms) |"
  echo "|---|---|---|---|---|"
  for scene in plane two_planes cluttered; do
    d=$work/ideal.$scene
    echo "| $scene | $(share "$(field "$d" "disparity density" | first)") % | $(share "$(field "$d" "estimated events within 1 px" | first)") % | $(lifetimeError "$d") | $(lifetimeError "$d.published") |"
  done
fi

if wanted pendulum; then
  echo
  echo "| mode | matching rate | left signal events 1-2 px off / over 2 px off / without a disparity |"
  echo "|---|---|---|"
  for run in "${pendulumRuns[@]}"; do
    m=${run%%:*}
    list=${run#*:}
    d=$work/pend.$m.$(key "$list")
    echo "| $m${list:+, \`$list\`} | $(decimal "$(field "$d" "ground truth: matching rate" | first)") % | $(field "$d" "ground truth: left signal events 1-2 px off") |"
  done
fi

if wanted tum && [ -d "$tum" ]; then
  # The share of events with a disparity / the share of those near the recording's disparity / the share of
  # all events near it, over the left camera's events (the page's awk line).
  near() {  # near EVENTS-CSV LOW HIGH
    awk -F, -v lo="$2" -v hi="$3" 'NR > 1 && $9 % 512 < 128 { n++; if ($6 >= 0) { d++; if ($6 >= lo && $6 <= hi) ok++ } }
      END { if (n == 0 || d == 0) print "failed"; else printf "%.1f / %.1f / %.1f %%", 100 * d / n, 100 * ok / d, 100 * ok / n }' "$1"
  }
  echo
  echo "| setting | Fan_disp8 | movingPersons | pendulum (\`--max-disparity=50\`) |"
  echo "|---|---|---|---|"
  for row in "${tumRows[@]}"; do
    k=$(key "$row")
    label=${row:+\`--set=$row\`}
    echo "| ${label:-defaults} | $(near "$work/tum.fan.$k/events.csv" 6.5 9.5) | $(near "$work/tum.mp.$k/events.csv" 11.5 14.5) | $(near "$work/tum.pendulum.$k/events.csv" 15.5 42.5) |"
  done
fi
