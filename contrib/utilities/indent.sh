#!/usr/bin/env bash
# Formats every C++ source and header of GelMPM with the repository's .clang-format.
#   bash contrib/utilities/indent.sh          format in place
#   bash contrib/utilities/indent.sh --check  list files that are not formatted (exit 1 if any)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
mapfile -t files < <(git ls-files '*.cc' '*.h' '*.h.in')
if [[ "${1:-}" == "--check" ]]; then
  bad=0
  for f in "${files[@]}"; do
    clang-format --dry-run --Werror "$f" >/dev/null 2>&1 || { echo "$f"; bad=1; }
  done
  exit $bad
fi
clang-format -i "${files[@]}"
