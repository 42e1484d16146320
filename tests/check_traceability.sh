#!/usr/bin/env bash
# Fails when a lemma listed in spec/traceability.md has no checking file in proofs-checks/.
# Table rows that give a reason instead of a check ("| not implemented: issue N", "| not
# computable", "| out of scope", "| not tested") are skipped: they list what has no file yet
# (tests/check_traceability_source.py checks those rows).
set -euo pipefail
root=${1:-.}
table="$root/spec/traceability.md"
[ -f "$table" ] || { echo "missing $table"; exit 1; }
missing=0
for l in $(grep -vE '\| *(not implemented|not computable|out of scope|not tested)' "$table" |
           grep -oE 'Lemma [0-9A]+\.[0-9]+' | sort -u | sed 's/Lemma //'); do
  key=$(echo "$l" | tr '.' '_' | tr 'A-Z' 'a-z')
  if ! ls "$root/proofs-checks" | grep -qiE "^lemma_${key}_.*\.cpp$"; then
    echo "spec/traceability.md lists Lemma $l but proofs-checks/ has no lemma_${key}_*.cpp"
    missing=1
  fi
done
[ $missing -eq 0 ] && echo "traceability: every lemma in the table has a checking file"
exit $missing
