#!/usr/bin/env bash
# Installs every Debian 12 package shadowkit needs (run as root on a fresh machine).
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev libosd-dev
  nlohmann-json3-dev libcli11-dev libpng-dev
  libtinygltf-dev libassimp-dev assimp-utils assimp-testmodels libabsl-dev liberfa-dev
  libgtest-dev libgmock-dev libbenchmark-dev python3 clang-format-14  # tests: layering, format
  clang-14 libfuzzer-14-dev libclang-rt-14-dev  # fuzz/: docs/fuzzing.md
  slurmctld slurmd slurm-client munge  # sun-study cluster test: scripts/slurm
  libcpp-httplib-dev libwebsocketpp-dev libasio-dev  # shadowkit serve
  chromium  # the viewer's browser test (src/app/viewer/browser_test), with node below
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
# Node.js and npm for the browser test's puppeteer-core: Debian's, unless a node with its own
# npm is already installed (NodeSource's nodejs package bundles npm and conflicts with
# Debian's npm package).
if ! command -v npm >/dev/null; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq --no-install-recommends nodejs npm
fi
