#!/usr/bin/env bash
# Every tracked C++ file formatted with the repository's .clang-format (clang-format from
# Debian 12, version 14). Lists the files that are not and exits 1; `clang-format -i FILE`
# formats one.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "check-format: clang-format not found (apt-get install clang-format)"; exit 1; }
bad=0
while IFS= read -r f; do
  if ! clang-format --dry-run --Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f (clang-format -i $f)"
    bad=1
  fi
done < <(git ls-files --cached --others --exclude-standard '*.cpp' '*.hpp' '*.h')
exit $bad
