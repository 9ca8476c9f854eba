#!/usr/bin/env bash
# Runs the assimp-testmodels corpus test and writes its summary (files tried and loaded per
# format, against `assimp info -r`) into docs/formats.md between the corpus markers.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target corpus_test >/dev/null
summary=$(mktemp)
trap 'rm -f "$summary" "$summary.md"' EXIT
SHADOWKIT_CORPUS_SUMMARY=$summary "$build/src/app/corpus_test" >/dev/null
doc=$root/docs/formats.md
awk -v summary="$summary" '
  /<!-- corpus:begin -->/ { print; while ((getline line < summary) > 0) print line; skip = 1; next }
  /<!-- corpus:end -->/ { skip = 0 }
  !skip { print }
' "$doc" > "$summary.md"
mv "$summary.md" "$doc"
echo "docs/formats.md: corpus summary updated"
