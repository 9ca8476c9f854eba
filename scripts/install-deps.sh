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
