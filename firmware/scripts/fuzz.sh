#!/bin/sh
# Builds the libFuzzer targets of the firmware core (firmware/fuzz, clang with
# ASan + UBSan, in its own build directory) and runs each for a bounded time,
# starting from seeds generated from the golden vectors.
#
#   bash firmware/scripts/fuzz.sh                 # every target, 30 s in all
#   FUZZ_SECONDS=3600 bash firmware/scripts/fuzz.sh json_reader
#
# Targets: cube_keyless cube_keyed json_reader deframer.
# Env: FUZZ_SECONDS (per target; default splits 30 s), FUZZ_BUILD_DIR,
# FUZZ_CORPUS_DIR (kept between runs; default inside the build dir),
# FUZZ_JOBS (build parallelism, and how many targets fuzz at once, each on one
# core; default 2), FUZZ_SEED (the bounded run's
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

# In pairs of equal budgets, since they run two at a time.
all="cube_keyless cube_keyed json_reader deframer"
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

mkdir -p "$artifacts" "$build/logs"

# One target's bounded run; its log is $build/logs/<target>.log, its exit code the run's.
fuzz_one() {
  t=$1
  corpus=$corpora/$t
  mkdir -p "$corpus"
  case $t in
    deframer) dict=$here/fuzz/frame.dict; max_len=4096 ;;
    json_reader) dict=$here/fuzz/cube.dict; max_len=1100 ;;
    *) dict=$here/fuzz/cube.dict; max_len=1400 ;;
  esac
  # New inputs go to the first directory (the kept corpus); the seeds and
  # the reproducers of past findings (firmware/fuzz/regressions) are read.
  regressions=
  [ -d "$here/fuzz/regressions/$t" ] && regressions=$here/fuzz/regressions/$t
  # shellcheck disable=SC2086 # $regressions is empty or one path
  "$build/fuzz_$t" "$corpus" "$build/seeds/$t" $regressions \
    -dict="$dict" -max_len="$max_len" -max_total_time="$(budget "$t")" \
    -seed="$seed" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="$artifacts/$t-" >"$build/logs/$t.log" 2>&1
}

# Prints a finished target's executions and coverage, or its finding; false on a finding.
report() {
  t=$1
  status=$2
  tlog=$build/logs/$t.log
  seconds=$(budget "$t")
  if [ "$status" -eq 0 ]; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$tlog" | tail -n 1)
    [ -n "$runs" ] || runs=$(sed -n 's/^Done \([0-9]*\) runs.*/\1/p' "$tlog" | tail -n 1)
    cov=$(grep -E '^#[0-9]+.*(DONE|INITED)' "$tlog" | tail -n 1 |
      sed -n 's/.*cov: \([0-9]*\).*/\1/p')
    printf 'fuzz %-13s %9s executions in %ss, coverage %s, no finding\n' \
      "$t" "${runs:-?}" "$seconds" "${cov:-?}"
    return 0
  fi
  grep -v -E '^(#[0-9]+|INFO:)' "$tlog" | tail -n 60 >&2
  found=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$tlog" | tail -n 1)
  echo "fuzz $t: FINDING; reproducer: ${found:-see the log above}" >&2
  echo "  re-run: $build/fuzz_$t ${found:-<file>}" >&2
  return 1
}

# Each libFuzzer run is single-threaded: the targets run $jobs at a time, each
# with its whole budget of one core's time, so the run takes about half as long
# on two cores and explores as much. Results print in the order given.
failed=0
set -- $targets
while [ $# -gt 0 ]; do
  started=
  n=0
  while [ $# -gt 0 ] && [ "$n" -lt "$jobs" ]; do
    fuzz_one "$1" &
    started="$started $1:$!"
    n=$((n + 1))
    shift
  done
  for entry in $started; do
    status=0
    wait "${entry#*:}" || status=$?
    report "${entry%%:*}" "$status" || failed=1
  done
done
exit $failed
