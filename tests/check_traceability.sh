#!/usr/bin/env bash
# Fails when a lemma listed in spec/traceability.md has no checking file in proofs-checks/.
set -euo pipefail
root=${1:-.}
table="$root/spec/traceability.md"
[ -f "$table" ] || { echo "missing $table"; exit 1; }
missing=0
for l in $(grep -oE 'Lemma [0-9A]+\.[0-9]+' "$table" | sort -u | sed 's/Lemma //'); do
  key=$(echo "$l" | tr '.' '_' | tr 'A-Z' 'a-z')
  if ! ls "$root/proofs-checks" | grep -qiE "^lemma_${key}_.*\.cpp$"; then
    echo "spec/traceability.md lists Lemma $l but proofs-checks/ has no lemma_${key}_*.cpp"
    missing=1
  fi
done
[ $missing -eq 0 ] && echo "traceability: every lemma in the table has a checking file"
exit $missing
