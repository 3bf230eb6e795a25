#!/usr/bin/env bash
# Fails, naming each file, when a C++ file of the repository is not in the house format (.clang-format,
# clang-format 14). To fix: `clang-format -i FILE`.
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."
scripts/setup.sh
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
[ ${#files[@]} -gt 0 ] || { echo "format_check: no C++ files found (not a git clone?)" >&2; exit 1; }
# One call for all: clang-format names each file and line that differs ("FILE:LINE:COL: error: code
# should be clang-formatted").
diagnostics=$(mktemp)
trap 'rm -f "$diagnostics"' EXIT
if ! clang-format --dry-run --Werror "${files[@]}" 2>"$diagnostics"; then
  grep -o '^[^:]*:[0-9]*' "$diagnostics" | cut -d: -f1 | sort -u |
    sed 's/^/format_check: not in the house format (clang-format -i): /' >&2
  exit 1
fi
echo "format_check: ${#files[@]} C++ files in the house format"
