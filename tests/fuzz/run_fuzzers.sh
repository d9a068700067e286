#!/bin/bash
# SPDX-License-Identifier: MIT
# Runs each libFuzzer target of a -DBUILD_FUZZERS=ON build for SECONDS, from its seed corpus
# (tests/fuzz/corpus/NAME, read only) and a working corpus in the build directory, and prints
# one row a target: executions, inputs in the working corpus, crashes. A crash, a leak, a
# sanitizer report or a timeout (60 s on one input: a tracker input, 120 frames under ASan and
# coverage, takes 2.5 s of CPU, and a shared machine may give it a seventh of a core) fails the
# run; the input is kept in BUILD/fuzz-crashes/NAME/, to be fixed and added to
# tests/fuzz/regressions/NAME/ (replayed by the unit test fuzz_NAME_replay). Slow inputs
# (slow-unit-*, over 10 s) are kept there too but fail nothing.
# usage: run_fuzzers.sh BUILD SECONDS [NAME...]
set -u
build=$1
seconds=$2
shift 2
names=("$@")
[ ${#names[@]} -gt 0 ] || names=(ini set control tracker)
source_dir="$(cd "$(dirname "$0")" && pwd)"
failed=0
printf '%-10s %8s %12s %8s %8s\n' target seconds executions kept crashes
for name in "${names[@]}"; do
  fuzzer="$build/tests/fuzz/fuzz_$name"
  work="$build/fuzz-corpus/$name"
  crashes="$build/fuzz-crashes/$name"
  log="$build/fuzz-$name.log"
  mkdir -p "$work" "$crashes"
  [ -x "$fuzzer" ] || { echo "$fuzzer: not built (cmake --build $build --target fuzzers)"; exit 1; }
  # The tracker's inputs are frame scripts: 2 kB hold settings and 120 frames of 4 bytes.
  max_len=4096
  [ "$name" = tracker ] && max_len=2048
  "$fuzzer" -max_total_time="$seconds" -timeout=60 -max_len="$max_len" -print_final_stats=1 \
    -artifact_prefix="$crashes/" "$work" "$source_dir/corpus/$name" >"$log" 2>&1
  status=$?
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  kept=$(find "$work" -type f | wc -l)
  found=$(find "$crashes" -type f ! -name 'slow-unit-*' | wc -l)
  printf '%-10s %8s %12s %8s %8s\n' "$name" "$seconds" "${executions:-?}" "$kept" "$found"
  if [ "$status" -ne 0 ] || [ "$found" -ne 0 ]; then
    echo "fuzz_$name failed (exit $status); the end of $log:"
    tail -40 "$log"
    failed=1
  fi
done
exit "$failed"
