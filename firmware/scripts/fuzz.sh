#!/bin/sh
# Builds the libFuzzer targets of the firmware core (firmware/fuzz, clang with
# ASan + UBSan, in its own build directory) and runs each for a bounded time,
# starting from seeds generated from the golden vectors.
#
#   bash firmware/scripts/fuzz.sh                 # every target, 30 s in all
#   FUZZ_SECONDS=3600 bash firmware/scripts/fuzz.sh json_reader
#
# Targets: json_reader cube_keyless cube_keyed deframer.
# Env: FUZZ_SECONDS (per target; default splits 30 s), FUZZ_BUILD_DIR,
# FUZZ_CORPUS_DIR (kept between runs; default inside the build dir),
# FUZZ_JOBS (build parallelism, default 2), FUZZ_SEED (the bounded run's
# default is seed 1, so the test command explores the same inputs on every
# machine and a red run is a finding anyone can reproduce; a run given
# FUZZ_SECONDS draws a random seed unless FUZZ_SEED is set).
# Prints the executions per target; exits non-zero on any finding and names
# the reproducer (a crash-*/leak-*/timeout-*/oom-* file): re-run it with
#   firmware/build-fuzz/fuzz_<target> <file>
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
build=${FUZZ_BUILD_DIR:-$here/build-fuzz}
corpora=${FUZZ_CORPUS_DIR:-$build/corpus}
artifacts=$build/findings
jobs=${FUZZ_JOBS:-2}
log=$(mktemp)
trap 'rm -f "$log"' EXIT

all="json_reader cube_keyless cube_keyed deframer"
targets=${*:-$all}
# Default budget: 30 s in all, weighted toward the request handler. The test command's run is a
# smoke run of fixed seed; the search for new findings is a long run (FUZZ_SECONDS).
budget() {
  if [ -n "${FUZZ_SECONDS:-}" ]; then echo "$FUZZ_SECONDS"; return; fi
  case $1 in
    cube_keyless | cube_keyed) echo 9 ;;
    *) echo 6 ;;
  esac
}

for t in $targets; do
  case " $all " in
    *" $t "*) ;;
    *) echo "fuzz: unknown target '$t' (targets: $all)" >&2; exit 2 ;;
  esac
done

if ! cmake -S "$here/fuzz" -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ \
  >"$log" 2>&1; then
  cat "$log" >&2
  echo "fuzz: cmake configure failed (needs clang and libclang-rt-dev)" >&2
  exit 1
fi
if ! cmake --build "$build" -j "$jobs" >"$log" 2>&1; then
  cat "$log" >&2
  echo "fuzz: build failed" >&2
  exit 1
fi

if [ -n "${FUZZ_SEED:-}" ]; then
  seed=$FUZZ_SEED
elif [ -n "${FUZZ_SECONDS:-}" ]; then
  seed=0 # libFuzzer picks one
else
  seed=1
fi

mkdir -p "$artifacts"
failed=0
for t in $targets; do
  corpus=$corpora/$t
  mkdir -p "$corpus"
  case $t in
    deframer) dict=$here/fuzz/frame.dict; max_len=4096 ;;
    json_reader) dict=$here/fuzz/cube.dict; max_len=1100 ;;
    *) dict=$here/fuzz/cube.dict; max_len=1400 ;;
  esac
  seconds=$(budget "$t")
  # New inputs go to the first directory (the kept corpus); the seeds and
  # the reproducers of past findings (firmware/fuzz/regressions) are read.
  regressions=
  [ -d "$here/fuzz/regressions/$t" ] && regressions=$here/fuzz/regressions/$t
  # shellcheck disable=SC2086 # $regressions is empty or one path
  if "$build/fuzz_$t" "$corpus" "$build/seeds/$t" $regressions \
    -dict="$dict" -max_len="$max_len" -max_total_time="$seconds" \
    -seed="$seed" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$artifacts/$t-" >"$log" 2>&1; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    [ -n "$runs" ] || runs=$(sed -n 's/^Done \([0-9]*\) runs.*/\1/p' "$log" | tail -n 1)
    cov=$(grep -E '^#[0-9]+.*(DONE|INITED)' "$log" | tail -n 1 |
      sed -n 's/.*cov: \([0-9]*\).*/\1/p')
    printf 'fuzz %-13s %9s executions in %ss, coverage %s, no finding\n' \
      "$t" "${runs:-?}" "$seconds" "${cov:-?}"
  else
    failed=1
    grep -v -E '^(#[0-9]+|INFO:)' "$log" | tail -n 60 >&2
    found=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -n 1)
    echo "fuzz $t: FINDING; reproducer: ${found:-see the log above}" >&2
    echo "  re-run: $build/fuzz_$t ${found:-<file>}" >&2
  fi
done
exit $failed
