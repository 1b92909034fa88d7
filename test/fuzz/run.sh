#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan, in build-fuzz/ of the clone, ccache) and runs each, as
# many at a time as there are cores.
#
#   test/fuzz/run.sh [--runs N | --seconds S] [target ...]
#
# Targets: text dat raw aedat2 aedat3 aedat4 rosbag1 rosbag2 mcap hdf5 davis_decoder (default: all).
# Default: 1,000,000 executions each. Seeds: test/fuzz/corpus/<target> (committed, from make_seeds.py),
# AEDAT 4.0 files the module's writer makes, and the real samples of ../shared/data/format_samples when
# present. New inputs go to build-fuzz/corpus/<target>, never into the repository. A crash, leak, timeout,
# out-of-memory or broken invariant stops that target with libFuzzer's report, and the run ends with a non-zero
# exit status once the others are done; the input that did it is saved as build-fuzz/artifacts/<target>-crash-*.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/../.." && pwd)
cache=${OPENCV_EVENT_CACHE:-/var/cache/opencv_event}
build=${OPENCV_EVENT_FUZZ_BUILD:-$repo/build-fuzz}
budget=(-runs=1000000)
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) budget=(-runs="$2"); shift 2 ;;
    --seconds) budget=(-max_total_time="$2"); shift 2 ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(text dat raw aedat2 aedat3 aedat4 rosbag1 rosbag2 mcap hdf5 davis_decoder)
command -v clang++ >/dev/null || { echo "run.sh: needs clang (apt-get install clang)" >&2; exit 1; }

export CCACHE_DIR=${CCACHE_DIR:-$cache/ccache}
export CCACHE_BASEDIR=$repo
export CCACHE_NOHASHDIR=1
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
echo "== fuzz: building in $build"
CC=clang CXX=clang++ cmake -S "$repo" -B "$build" -G Ninja "${launcher[@]}" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DOPENCV_EVENT_BUILD_TESTS=OFF -DOPENCV_EVENT_BUILD_PERF_TESTS=OFF -DOPENCV_EVENT_BUILD_SAMPLES=OFF \
  -DOPENCV_EVENT_BUILD_BENCHMARKS=OFF -DOPENCV_EVENT_BUILD_CONTRIB_TEST=OFF -DOPENCV_EVENT_BUILD_FUZZERS=ON -DOPENCV_EVENT_BUILD_PYTHON=OFF \
  > "$build.configure.log" 2>&1 || { tail -40 "$build.configure.log"; exit 1; }
cmake --build "$build" > "$build.build.log" 2>&1 || { tail -60 "$build.build.log"; exit 1; }

shared="${OPENCV_EVENT_SHARED_DATA:-$repo/../shared/data}/format_samples"
extra_seeds() {  # the real samples of one format, when ../shared/data is there
  [ -d "$shared" ] || return 0
  case "$1" in
    aedat4) ls "$shared"/*.aedat4 ;;
    raw) ls "$shared"/*.raw ;;
    dat) ls "$shared"/*.dat ;;
    rosbag1) ls "$shared"/*.bag ;;
    rosbag2) find "$shared" -name '*.db3' ;;
    mcap) find "$shared" -name '*.mcap' ;;
  esac 2>/dev/null || true
}

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions="$repo/test/lsan.supp"
export TMPDIR=${TMPDIR:-/tmp}
mkdir -p "$build/artifacts"
# One target: its log in $build/fuzz_<t>.log, its summary line in $build/fuzz_<t>.summary; non-zero on a finding.
fuzz_one() {
  local t=$1 exe="$build/test/fuzz/fuzz_$1" work="$build/corpus/$1" seeds_dir="$build/seeds/$1"
  local log="$build/fuzz_$1.log" start runs
  mkdir -p "$work"
  cp -n "$here/corpus/$t"/* "$work"/ 2>/dev/null || true
  [ "$t" != aedat4 ] || "$build/test/fuzz/fuzz_write_seeds" "$work"
  rm -rf "$seeds_dir"; mkdir -p "$seeds_dir"
  while IFS= read -r f; do [ -n "$f" ] && ln -sf "$f" "$seeds_dir/"; done < <(extra_seeds "$t")
  echo "== fuzz: $t (${budget[*]})"
  start=$(date +%s)
  # -max_len 64 KiB: real samples are cut to their first 64 KiB; -malloc_limit_mb: a header claiming 2^40
  # events must not make the reader allocate it.
  if ! "$exe" "${budget[@]}" -max_len=65536 -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
       -artifact_prefix="$build/artifacts/$t-" -print_final_stats=1 "$work" "$seeds_dir" > "$log" 2>&1; then
    tail -60 "$log"
    echo "== fuzz: $t FAILED (log: $log)"
    return 1
  fi
  runs=$(grep -o 'Done [0-9]* runs' "$log" | grep -o '[0-9]*' || echo "?")
  printf '%-14s %10s executions  %5d s  corpus %4d files\n' "$t" "$runs" $(( $(date +%s) - start )) \
    "$(ls "$work" | wc -l)" > "$build/fuzz_$t.summary"
}

for t in "${targets[@]}"; do
  [ -x "$build/test/fuzz/fuzz_$t" ] || { echo "run.sh: unknown target $t" >&2; exit 2; }
  rm -f "$build/fuzz_$t.summary" "$build/fuzz_$t.status"
done
# The targets run as many at a time as there are cores; each one's status is kept in a file, since wait -n,
# which keeps the count down, reaps them in any order.
parallel=$(nproc)
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$parallel" ]; do wait -n || true; done
  { s=0; fuzz_one "$t" || s=$?; echo "$s" > "$build/fuzz_$t.status"; } &
done
wait
failed=0
for t in "${targets[@]}"; do
  [ "$(cat "$build/fuzz_$t.status" 2>/dev/null)" = 0 ] || { echo "== fuzz: $t did not pass"; failed=1; }
done
[ "$failed" = 0 ] || exit 1
echo "== fuzz: no crash, leak, timeout or broken invariant"
for t in "${targets[@]}"; do cat "$build/fuzz_$t.summary"; done
