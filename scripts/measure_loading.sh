#!/usr/bin/env bash
# Loading against scan conversion, on the 2000-cube field as an OBJ file, the glTF engine and
# the IFC house of assimp-testmodels: `shadowkit info` wall time and the loading time inside
# `bench` (load_ms), beside one 1920x1080 scan conversion of the same scene (scan_ms), medians
# of RUNS runs. The IFC house twice: imported by assimp (import cache off) and from the cache.
#   bash scripts/measure_loading.sh [RUNS]    (build/shadowkit must exist: scripts/build.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shadowkit=${SHADOWKIT:-$root/build/shadowkit}
runs=${1:-9}
models=/usr/share/assimp/models
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The 2000 cubes of `cubes:2000`'s grid (13 slots a side, cubes half a slot wide) as quads.
awk 'BEGIN {
  n = 0; s = 10 / 13; h = s / 4
  for (i = 0; i < 13 && n < 2000; i++) for (j = 0; j < 13 && n < 2000; j++)
  for (k = 0; k < 13 && n < 2000; k++) {
    x = -5 + (i + 0.5) * s; y = 0.5 + (j + 0.5) * s; z = -5 + (k + 0.5) * s
    for (c = 0; c < 8; c++)
      printf "v %.6f %.6f %.6f\n", x + (c % 2 ? h : -h), y + (int(c / 2) % 2 ? h : -h), z + (c >= 4 ? h : -h)
    b = n * 8; n++
    printf "f %d %d %d %d\nf %d %d %d %d\nf %d %d %d %d\n", b+1,b+3,b+4,b+2, b+5,b+6,b+8,b+7, b+1,b+2,b+6,b+5
    printf "f %d %d %d %d\nf %d %d %d %d\nf %d %d %d %d\n", b+3,b+7,b+8,b+4, b+1,b+5,b+7,b+3, b+2,b+4,b+8,b+6
  }
}' > "$work/cubes-2000.obj"

median() { sort -g | awk '{ v[NR] = $1 } END { printf "%.1f", (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
json_number() { grep -o "\"$1\": [0-9.e+-]*" | head -1 | awk '{ print $2 }'; }

measure() {  # LABEL FILE [ENV...]
  local label=$1 file=$2; shift 2
  local info=() load=() scan=()
  for ((r = 0; r < runs; r++)); do
    local start end out
    start=$(date +%s%N)
    env "$@" "$shadowkit" info "$file" >/dev/null 2>&1
    end=$(date +%s%N)
    info+=("$(awk -v ns=$((end - start)) 'BEGIN { printf "%.1f", ns / 1e6 }')")
    out=$(env "$@" "$shadowkit" bench "$file" --methods raytrace --warmup 1 --repeats 3 --json 2>/dev/null)
    load+=("$(json_number load_ms <<< "$out")")
    scan+=("$(json_number scan_ms <<< "$out")")
  done
  printf "| %s | %s | %s | %s |\n" "$label" \
    "$(printf '%s\n' "${info[@]}" | median)" "$(printf '%s\n' "${load[@]}" | median)" \
    "$(printf '%s\n' "${scan[@]}" | median)"
}

echo "| model | info, whole command (ms) | load_ms | scan_ms (1920x1080) |"
echo "|---|---:|---:|---:|"
measure "2000 cubes, OBJ (12,000 quads)" "$work/cubes-2000.obj"
measure "2CylinderEngine.glb (110,336 triangles, 83 nodes)" "$models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb"
measure "AC14-FZK-Haus.ifc, assimp import (16,069 polygons)" "$models/IFC/AC14-FZK-Haus.ifc" SHADOWKIT_CACHE_DIR=
SHADOWKIT_CACHE_DIR="$work/cache" "$shadowkit" info "$models/IFC/AC14-FZK-Haus.ifc" >/dev/null 2>&1
measure "AC14-FZK-Haus.ifc, from the import cache" "$models/IFC/AC14-FZK-Haus.ifc" SHADOWKIT_CACHE_DIR="$work/cache"
