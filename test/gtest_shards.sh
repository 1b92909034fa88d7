#!/usr/bin/env bash
# Runs a gtest program as one shard per core, at most 8, at once (gtest's GTEST_TOTAL_SHARDS /
# GTEST_SHARD_INDEX: each test in exactly one shard), so a 2-core machine runs the single-threaded tests two at
# a time. Each shard's output is shown whole after all have ended, in shard order; the status is the first
# failing shard's (0 when all pass).
#
#   test/gtest_shards.sh PROGRAM [gtest arguments ...]
#   GTEST_SHARD_FILTERS='FILTER;FILTER;...' test/gtest_shards.sh PROGRAM [gtest arguments ...]
#
# With GTEST_SHARD_FILTERS each shard is one process running one of the given --gtest_filter patterns: for a
# few long tests that gtest's round robin would put on the same shard.
set -uo pipefail
[ $# -gt 0 ] || { echo "usage: gtest_shards.sh PROGRAM [arguments ...]" >&2; exit 2; }
filters=()
if [ -n "${GTEST_SHARD_FILTERS:-}" ]; then
  IFS=';' read -r -a filters <<< "$GTEST_SHARD_FILTERS"
  shards=${#filters[@]}
else
  shards=$(nproc)
  [ "$shards" -le 8 ] || shards=8
fi
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
pids=()
for ((i = 0; i < shards; i++)); do
  if [ ${#filters[@]} -gt 0 ]; then
    "$@" --gtest_filter="${filters[$i]}" > "$logs/$i.log" 2>&1 &
  else
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "$@" > "$logs/$i.log" 2>&1 &
  fi
  pids+=($!)
done
status=0
for ((i = 0; i < shards; i++)); do
  wait "${pids[$i]}"
  s=$?
  echo "== gtest_shards: shard $((i + 1)) of $shards, status $s"
  cat "$logs/$i.log"
  if [ ${#filters[@]} -gt 0 ] && ! grep -q '^\[  PASSED  \] [1-9]' "$logs/$i.log" && [ "$s" = 0 ]; then
    echo "== gtest_shards: no test matches --gtest_filter=${filters[$i]}"
    s=1
  fi
  [ "$status" != 0 ] || status=$s
done
exit "$status"
