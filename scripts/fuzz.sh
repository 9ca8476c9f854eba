#!/usr/bin/env bash
# Fuzzing by hand (docs/fuzzing.md).
#   scripts/fuzz.sh [--build asan|release] [--jobs N] [--no-build] TARGET|all MINUTES
#       builds the fuzz targets, then fuzzes TARGET (or every target, one after another) for
#       MINUTES minutes each, past crashes, hangs and out-of-memory inputs, and prints a summary.
#   scripts/fuzz.sh build asan|release      only builds the targets
#   scripts/fuzz.sh list                    lists the targets
# Builds: asan (ASan + UBSan, default) in build-fuzz-asan/, release (-O3, no sanitizer) in
# build-fuzz-release/ (SHADOWKIT_FUZZ_BUILD_DIR overrides). The corpus of each target persists
# in $SHADOWKIT_FUZZ_HOME/corpus/TARGET (default ~/.cache/shadowkit-fuzz); the crash-*,
# timeout-*, oom-*, leak-* and slow-unit-* (over 10 s) inputs and the logs go to
# $SHADOWKIT_FUZZ_HOME/findings/BUILD/TARGET/; those that do not fail again when replayed, to
# its unreproduced/. Exit status 1 when anything but slow inputs was found.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
source "$root/fuzz/common.sh"

usage() {
  awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0" >&2
  exit 2
}

build_dir() { echo "${SHADOWKIT_FUZZ_BUILD_DIR:-$root/build-fuzz-$1}"; }

build() {
  local kind=$1 type sanitize
  case $kind in
    asan) type=RelWithDebInfo sanitize=ON ;;
    release) type=Release sanitize=OFF ;;
    *) usage ;;
  esac
  cmake -S "$root" -B "$(build_dir "$kind")" -G Ninja \
    -DCMAKE_CXX_COMPILER="${SHADOWKIT_FUZZ_CXX:-clang++-14}" -DCMAKE_BUILD_TYPE=$type \
    -DSHADOWKIT_SANITIZE=$sanitize -DSHADOWKIT_FUZZ=ON \
    -DSHADOWKIT_TESTS=OFF -DSHADOWKIT_BENCHMARKS=OFF >/dev/null
  cmake --build "$(build_dir "$kind")" --target fuzzers
}

build_kind=asan jobs=1 do_build=1
case ${1:-} in
  build) (($# == 2)) || usage; build "$2"; exit ;;
  list) fuzz_targets | tr ' ' '\n'; exit ;;
esac
while (($#)); do
  case $1 in
    --build) build_kind=${2:-}; shift 2 ;;
    --jobs) jobs=${2:-}; shift 2 ;;
    --no-build) do_build=0; shift ;;
    -*) usage ;;
    *) break ;;
  esac
done
(($# == 2)) || usage
[[ $2 =~ ^[0-9]+$ && $jobs =~ ^[1-9][0-9]*$ ]] || usage
if [[ $1 == all ]]; then
  read -ra targets <<<"$(fuzz_targets)"
else
  targets=("$1")
fi
minutes=$2
home=${SHADOWKIT_FUZZ_HOME:-$HOME/.cache/shadowkit-fuzz}
((do_build)) && build "$build_kind"
bin_dir=$(build_dir "$build_kind")/fuzz

found=0
summaries=()
for name in "${targets[@]}"; do
  binary=$bin_dir/fuzz_$name
  [[ -x $binary ]] || { echo "no fuzz target '$name' in $bin_dir (scripts/fuzz.sh list)" >&2; exit 2; }
  corpus=$home/corpus/$name
  findings=$home/findings/$build_kind/$name
  work=$home/work/$build_kind-$name
  log=$findings/$(date +%Y%m%d-%H%M%S).log
  rm -rf "$work"
  mkdir -p "$corpus" "$findings" "$work/tmp"
  fuzz_collect_seeds "$(fuzz_kind "$name")" "$work/seeds"
  mapfile -t regressions < <(fuzz_regression_dirs "$name")
  mapfile -t options < <(fuzz_options "$name")
  touch "$work/start"
  echo "fuzzing $name ($build_kind build) for $minutes min, $jobs job(s); log: $log"
  # Fork mode: each job is a child process; a crash, hang or oom is saved and counted, and
  # fuzzing goes on.
  TMPDIR=$work/tmp "$binary" "${options[@]}" -fork="$jobs" -ignore_crashes=1 \
    -ignore_timeouts=1 -ignore_ooms=1 -max_total_time=$((minutes * 60)) \
    -artifact_prefix="$findings/" "$corpus" "${regressions[@]}" "$work/seeds" >"$log" 2>&1 ||
    true
  # The last status line of fork mode: "#EXECS: cov: .. exec/s: .. oom/timeout/crash: ..
  # time: Ss ...". Its counts leave out the inputs that fail as the run starts (the seeds and
  # regression inputs), so the findings are counted as the files saved.
  stats=$(grep -aoE '#[0-9]+: cov: .* time: [0-9]+s' "$log" | tail -1 || true)
  execs=$(sed -n 's/^#\([0-9]*\):.*/\1/p' <<<"$stats")
  seconds=$(sed -n 's/.* time: \([0-9]*\)s.*/\1/p' <<<"$stats")
  # Each input saved is replayed once. One that passes then moves to unreproduced/ and is not
  # counted: an allocation of an importer's child process (the formats assimp reads), which
  # the reader reports as an InputError, or a hang of an overloaded machine.
  mkdir -p "$findings/unreproduced"
  while IFS= read -r -d '' file; do
    if TMPDIR=$work/tmp "$binary" "${options[@]}" "$file" >>"$log.replay" 2>&1; then
      mv "$file" "$findings/unreproduced/"
    fi
  done < <(find "$findings" -maxdepth 1 -newer "$work/start" \( -name 'crash-*' -o \
    -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) -print0)
  count() { find "$findings" -maxdepth 1 -name "$1-*" -newer "$work/start" | wc -l; }
  crashes=$(count crash) timeouts=$(count timeout) ooms=$(count oom) leaks=$(count leak)
  slow=$(count slow-unit)
  rate=$((${seconds:-0} > 0 ? ${execs:-0} / seconds : 0))
  summary="$name ($build_kind): ${execs:-0} executions in ${seconds:-0} s ($rate/s), corpus $(ls "$corpus" | wc -l) files; crashes $crashes, timeouts $timeouts, ooms $ooms, leaks $leaks; slow inputs (over 10 s) $slow"
  echo "$summary"
  summaries+=("$summary")
  if ((crashes + timeouts + ooms + leaks)); then
    found=1
    find "$findings" -maxdepth 1 -newer "$work/start" \
      \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) -printf '  %p\n'
  fi
  rm -rf "$work/tmp"
done
if ((${#targets[@]} > 1)); then
  echo "summary:"
  printf '  %s\n' "${summaries[@]}"
fi
exit $found
