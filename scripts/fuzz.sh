#!/usr/bin/env bash
# Fuzzes Loom's readers with libFuzzer (docs/fuzzing.md):
#
#   scripts/fuzz.sh [NAME...] [--runs N] [--no-build]
#
# (default: every target, 1000000 runs each; --no-build runs what build-fuzz/
# holds, e.g. to run two lists of targets side by side).
#
# Installs clang and libFuzzer if missing (through scripts/setup.sh), builds the
# harnesses with clang, ASan and UBSan into build-fuzz/, and runs each on a copy
# of its seed corpus (tests/fuzz/corpus/NAME; the copy grows, the seeds do not).
# A crash, timeout, leak or out-of-memory input is left in
# tests/fuzz/crashes/NAME/, where test_fuzz_replay replays it, and makes the
# script fail once every harness has run.
set -euo pipefail
cd "$(dirname "$0")/.."

all=(obj off vtk vtu msh rules schema cap database strategy)
runs=1000000
build_first=1
names=()
while (($#)); do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --runs=*) runs="${1#--runs=}"; shift ;;
    --no-build) build_first=0; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) names+=("$1"); shift ;;
  esac
done
((${#names[@]})) || names=("${all[@]}")
for n in "${names[@]}"; do
  [[ " ${all[*]} " == *" $n "* ]] || { echo "fuzz: no target '$n'; the targets are ${all[*]}" >&2; exit 2; }
done

# -O2 rather than the sanitizer build's -O1: the executions per second are the
# budget here. Debug keeps assert() on.
build=build-fuzz
if ((build_first)); then
  LOOM_EXTRA_PACKAGES="clang libclang-rt-14-dev" LOOM_BUILD_DIR=$build LOOM_BUILD_TYPE=Debug \
    LOOM_BUILD_TARGETS="${names[*]/#/fuzz_}" scripts/setup.sh \
    -DCMAKE_CXX_COMPILER=clang++ -DLOOM_FUZZ=ON -DCMAKE_CXX_FLAGS_DEBUG="-O2 -g"
fi

# Each target's -max_len is kept beside it, in the table of fuzz_targets.cpp.
max_len_of() {
  grep -oE "\{\"$1\", [a-z_]+, [0-9]+" tests/fuzz/fuzz_targets.cpp | grep -oE '[0-9]+$'
}

export UBSAN_OPTIONS=print_stacktrace=1
failed=()
rows=()
for n in "${names[@]}"; do
  work="$build/corpus/$n"
  crashes="tests/fuzz/crashes/$n"
  rm -rf "$work" && mkdir -p "$work" "$crashes"
  cp tests/fuzz/corpus/"$n"/* "$work"/
  log="$build/fuzz-$n.log"
  max_len=$(max_len_of "$n")
  echo "fuzz: $n: $runs runs, -max_len=$max_len (log: $log)"
  start=$EPOCHREALTIME
  status=0
  "$build/fuzz/fuzz_$n" -runs="$runs" -max_len="$max_len" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$crashes/" "$work" >"$log" 2>&1 || status=$?
  seconds=$(awk "BEGIN { print $EPOCHREALTIME - $start }")
  executed=$(grep -oE 'stat::number_of_executed_units: +[0-9]+' "$log" | grep -oE '[0-9]+$' || echo "?")
  per_second=$(grep -oE 'stat::average_exec_per_sec: +[0-9]+' "$log" | grep -oE '[0-9]+$' || echo "?")
  rmdir "$crashes" 2>/dev/null || true
  if ((status)); then
    failed+=("$n")
    grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$log" | head -5 || true
  fi
  rows+=("$(printf '%-9s %8s %12s %9s %9.0f  %s' "$n" "$max_len" "$executed" "$per_second" "$seconds" \
    "$( ((status)) && echo "FAILED ($status)" || echo ok)")")
done

printf '%-9s %8s %12s %9s %9s  %s\n' target max_len executions exec/s seconds result
printf '%s\n' "${rows[@]}"
if ((${#failed[@]})); then
  echo "fuzz: findings in ${failed[*]}: inputs kept in tests/fuzz/crashes/ (replayed by test_fuzz_replay)" >&2
  exit 1
fi
