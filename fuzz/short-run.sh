#!/usr/bin/env bash
# The test suite's short run of one fuzz target (CTest calls it; fuzz/CMakeLists.txt):
#   short-run.sh BINARY NAME RUNS WORKDIR
# Deterministic: libFuzzer -seed=1 and -runs=RUNS from the same seeds every time. The target
# replays its regression inputs and seeds first, then mutates. New corpus entries and any
# crash, timeout or out-of-memory input go to WORKDIR (emptied first), never into the source tree.
set -euo pipefail
binary=$1 name=$2 runs=$3 work=$4
source "$(dirname "$0")/common.sh"

rm -rf "$work"
mkdir -p "$work/corpus" "$work/artifacts" "$work/tmp"
fuzz_collect_seeds "$(fuzz_kind "$name")" "$work/seeds"
mapfile -t regressions < <(fuzz_regression_dirs "$name")
mapfile -t options < <(fuzz_options "$name")
export TMPDIR=$work/tmp
exec "$binary" "${options[@]}" -seed=1 -runs="$runs" -artifact_prefix="$work/artifacts/" \
  "$work/corpus" "${regressions[@]}" "$work/seeds"
