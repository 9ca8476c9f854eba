#!/usr/bin/env bash
# Every C++ file is formatted by .clang-format (ctest -R format). To reformat:
#   scripts/check_format.sh --fix
set -euo pipefail
cd "$(dirname "$0")/.."
format=$(command -v clang-format-14 || command -v clang-format)
mapfile -t files < <(find include src fuzz \( -name '*.h' -o -name '*.cpp' \) | sort)
if [[ ${1:-} == --fix ]]; then
  "$format" -i "${files[@]}"
else
  "$format" --dry-run --Werror "${files[@]}"
  echo "${#files[@]} files formatted as .clang-format says"
fi
