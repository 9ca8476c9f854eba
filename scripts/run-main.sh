#!/usr/bin/env bash
# The main job: install, build, and compare every method on the bundled default scene.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
"$root/build/shadowkit" compare "$root/examples/default.json" --report "$root/report"
