#!/usr/bin/env bash
# CTest runs the viewer's Node.js tests through this: run.sh SCRIPT.mjs ARGS...
# Their npm packages (package-lock.json) are installed by scripts/run-tests.sh.
set -euo pipefail
dir=$(cd "$(dirname "$0")" && pwd)
if [[ ! -d $dir/node_modules/puppeteer-core || ! -d $dir/node_modules/ws ]]; then
  echo "the viewer's browser tests need their npm packages: npm ci --prefix $dir" >&2
  exit 1
fi
script=$1
shift
exec node "$dir/$script" "$@"
