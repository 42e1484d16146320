#!/usr/bin/env bash
# The checked-in .clang-format is applied to every C++ file.
set -euo pipefail
cd "${1:-.}"
files=$(git ls-files '*.h' '*.cpp' 2>/dev/null || find src tests proofs-checks fuzz -name '*.h' -o -name '*.cpp')
clang-format --dry-run -Werror $files
echo "format: $(echo "$files" | wc -w) files follow .clang-format"
