#!/usr/bin/env bash
# The exact core must not mention floating point or tolerances.
set -euo pipefail
root=${1:-.}
if grep -rnE '\b(double|float)\b|to_double|epsilon|[0-9]e-[0-9]' "$root/src/symmesh/core"; then
  echo "src/symmesh/core must stay exact"
  exit 1
fi
echo "core is exact: no double, float, to_double or epsilon"
