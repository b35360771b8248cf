#!/usr/bin/env bash
# Every C++ file of the project is formatted by the root .clang-format; an unformatted one fails this test,
# named with clang-format's diagnostic. Fix with: clang-format -i FILE (or every file: see README.md).
# Usage: format_test.sh SOURCE_DIR
set -euo pipefail
cd "$1"
clang_format=$(command -v clang-format || command -v clang-format-14 || true)
if [ -z "$clang_format" ]; then
  echo "clang-format not found (Debian: clang-format; experiments/setup.sh installs it)"
  exit 1
fi
if [ -d .git ] || git rev-parse --git-dir >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
else
  mapfile -t files < <(find theory plots reports experiments checks -name '*.cpp' -o -name '*.hpp' -o -name '*.h')
fi
"$clang_format" --dry-run --Werror "${files[@]}"
echo "${#files[@]} files formatted"
