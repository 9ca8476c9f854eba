#!/usr/bin/env bash
# The whole test suite: install, build with AddressSanitizer + UBSan, run CTest (the viewer's
# tests drive headless Chromium through npm's puppeteer-core); then the fuzz
# targets, built with clang + ASan + UBSan: their short runs and regression inputs
# (docs/fuzzing.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install-deps.sh"
build=${BUILD_DIR:-$root/build-asan}
BUILD_DIR=$build BUILD_TYPE=RelWithDebInfo "$root/scripts/build.sh" -DSHADOWKIT_SANITIZE=ON \
  -DSHADOWKIT_WARNINGS_AS_ERRORS=ON
# The viewer's browser tests' npm packages, as locked (src/app/viewer/browser_test).
npm ci --prefix "$root/src/app/viewer/browser_test" --no-audit --no-fund --loglevel=error
fuzz_build=${FUZZ_BUILD_DIR:-$root/build-fuzz-asan}
SHADOWKIT_FUZZ_BUILD_DIR=$fuzz_build "$root/scripts/fuzz.sh" build asan
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
status=0
ctest --test-dir "$build" --output-on-failure -j 2 --timeout 600 || status=1
ctest --test-dir "$fuzz_build/fuzz" --output-on-failure -j 2 --timeout 600 || status=1
exit $status
