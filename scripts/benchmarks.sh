#!/usr/bin/env bash
# Regenerates docs/benchmarks.md and docs/benchmarks-summary.md: every method on every built-in
# scene and example scene at 1920x1080, timed with `shadowkit bench` (PASSES passes over the
# scenes; per scene each method in its own process between two timings of raytrace, REPEATS
# timed runs each) and compared with raytrace by `shadowkit compare`.
#   bash scripts/benchmarks.sh [--quick] [--repeats N] [--warmup N] [--passes P] [--threads N]
#                              [--out FILE] [--summary FILE] [--keep DIR]
#   --quick     one pass of one timed run, no warm-up, written to /tmp/benchmarks-quick.md
#               (and -summary.md) unless --out/--summary say otherwise: checks the script
#               (under a minute)
#   --threads   passed to every shadowkit command (default: all cores)
#   --keep      keep the raw JSON (bench, compare, info per scene) in DIR
#   --from      measure nothing: write the page again from the raw JSON a --keep run left in DIR
#   defaults    --repeats 9 --warmup 1 --passes 3 --out docs/benchmarks.md
#               --summary docs/benchmarks-summary.md (about 15 minutes on 2 cores)
# Needs build/shadowkit (BUILD_DIR=build bash scripts/build.sh) or SHADOWKIT=path, and python3.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shadowkit=${SHADOWKIT:-$root/build/shadowkit}
repeats=9 warmup=1 passes=3 quick=0
out= summary= keep= from= threads=()
shown=()  # the options that change what is measured, for the page's command line
while (($#)); do
  case $1 in
    --quick) quick=1 repeats=1 warmup=0 passes=1; shown+=("$1") ;;
    --repeats|--warmup|--passes|--threads) (($# > 1)) || { echo "benchmarks.sh: $1 needs a value" >&2; exit 2; }
      shown+=("$1" "$2") ;;&
    --repeats) repeats=$2; shift ;;
    --warmup) warmup=$2; shift ;;
    --passes) passes=$2; shift ;;
    --threads) threads=(--threads "$2"); shift ;;
    --out) out=$2; shift ;;
    --summary) summary=$2; shift ;;
    --keep) keep=$2; shift ;;
    --from) from=$2; shift ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "benchmarks.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done
if ((quick)); then
  out=${out:-/tmp/benchmarks-quick.md} summary=${summary:-/tmp/benchmarks-quick-summary.md}
else
  out=${out:-$root/docs/benchmarks.md} summary=${summary:-$root/docs/benchmarks-summary.md}
fi
if [[ -n $from ]]; then
  python3 "$root/scripts/benchmarks_report.py" report "$from" "$out" "$summary"
  exit
fi
[[ -x $shadowkit ]] || { echo "benchmarks.sh: no $shadowkit; run scripts/build.sh" >&2; exit 2; }

width=1920 height=1080
methods=raytrace,shadowmap,volume,svbsp,angular,voxel
scenes=(cubes:125 cubes:2000 cubes:8000 tetra:3 tetra:4 room table three-lights square coil holed
        hole-like examples/default.json examples/subdivision.json examples/room.json
        examples/open-meshes.json examples/formats.json)
helper=$root/scripts/benchmarks_report.py
if [[ -n $keep ]]; then
  mkdir -p "$keep"
  work=$(cd "$keep" && pwd)
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
start=$(date +%s)
load_start=$(cut -d' ' -f1 /proc/loadavg)

# Example files run from copies at width x height (built-in scenes are 1920x1080 already).
paths=()
for i in "${!scenes[@]}"; do
  s=${scenes[$i]}
  if [[ $s == *.json ]]; then
    python3 "$helper" widen "$root/$s" "$work/scene.$i.json" "$width" "$height"
    paths+=("$work/scene.$i.json")
  else
    paths+=("$s")
  fi
done

# Runs shadowkit; status 3 (a method failed on a light: a `failed` row) is a result, not an error.
run() {
  local status=0
  "$shadowkit" "$@" "${threads[@]}" || status=$?
  if ((status != 0 && status != 3)); then
    echo "benchmarks.sh: shadowkit $* ended with status $status" >&2
    exit 1
  fi
}

for i in "${!scenes[@]}"; do
  run info "${paths[$i]}" --json > "$work/info.$i.json"
  read -r w h < <(python3 -c 'import json, sys; c = json.load(open(sys.argv[1]))["camera"]; print(c["width"], c["height"])' "$work/info.$i.json")
  [[ "${w}x${h}" == "${width}x${height}" ]] || { echo "benchmarks.sh: ${scenes[$i]} is ${w}x${h}" >&2; exit 1; }
done
# Each method in its own process, between two timings of raytrace (the ratio's reference).
for ((p = 0; p < passes; p++)); do
  for i in "${!scenes[@]}"; do
    echo "benchmarks.sh: pass $((p + 1))/$passes: bench ${scenes[$i]}" >&2
    for m in ${methods//,/ }; do
      [[ $m == raytrace ]] && continue
      run bench "${paths[$i]}" --methods "raytrace,$m,raytrace" --repeats "$repeats" \
        --warmup "$warmup" --json > "$work/bench.$p.$i.$m.json"
    done
  done
done
for i in "${!scenes[@]}"; do
  echo "benchmarks.sh: compare ${scenes[$i]}" >&2
  run compare "${paths[$i]}" --methods "$methods" --json > "$work/compare.$i.json"
done

# What the page says about the machine, the build and the run.
build_dir=$(cd "$(dirname "$shadowkit")" && pwd)
cache=$build_dir/CMakeCache.txt
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$cache" 2>/dev/null | head -1; }
build_type=$(cache_value CMAKE_BUILD_TYPE)
flags=$(cache_value "CMAKE_CXX_FLAGS_${build_type^^}")
[[ $build_type == Release ]] && flags="-march=$(cache_value SHADOWKIT_MARCH) $flags"
compiler=$("$(cache_value CMAKE_CXX_COMPILER)" --version 2>/dev/null | head -1 || true)
embree=$(cache_value embree_DIR | sed -n 's/.*embree-\([0-9.]*\).*/\1/p')
command="bash scripts/benchmarks.sh"
((${#shown[@]})) && command+=" ${shown[*]}"
python3 - "$work/meta.json" <<EOF
import json, sys
scenes = """${scenes[*]}""".split()
cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "unknown CPU")
mhz = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("cpu MHz")), "?")
mem = next(int(l.split()[1]) for l in open("/proc/meminfo") if l.startswith("MemTotal"))
os_name = next((l.split("=", 1)[1].strip().strip('"') for l in open("/etc/os-release") if l.startswith("PRETTY_NAME=")), "Linux")
json.dump({
    "scenes": scenes, "passes": $passes, "repeats": $repeats, "warmup": $warmup,
    "size": "${width}x${height}", "cpu": cpu, "cpu_mhz": f"{float(mhz):.0f}" if mhz != "?" else mhz,
    "cores": $(nproc), "memory_gb": f"{mem / 2**20:.0f}", "os": os_name,
    "build": "${build_type:-unknown} ($flags), ${compiler:-unknown compiler}, Embree ${embree:-3}, built by scripts/build.sh",
    "command": "$command",
    "bench_command": "build/shadowkit bench SCENE --methods raytrace,METHOD,raytrace --repeats $repeats --warmup $warmup${threads[*]:+ ${threads[*]}} --json",
    "compare_command": "build/shadowkit compare SCENE --methods $methods${threads[*]:+ ${threads[*]}} --json",
    "threads": "${threads[1]:-}",
    "elapsed_min": ($(date +%s) - $start) / 60, "load_start": "$load_start",
    "load_end": "$(cut -d' ' -f1 /proc/loadavg)",
}, open(sys.argv[1], "w"), indent=1)
EOF
python3 "$helper" report "$work" "$out" "$summary"
echo "benchmarks.sh: wrote $out and $summary in $((($(date +%s) - start) / 60)) min" >&2
