#!/usr/bin/env bash
# symmesh generate --method merge (spec/generation.md#merge): every template meshed on its own,
# the interfaces sewn by Algorithm 5.3 (exact), the SVB read off the exact boundary complexes and
# Lemma 4.2 certified on them. On every built-in 2D object the output is certified, and read back
# with meshio it is conforming with the object's area and every triangle counter-clockwise
# (structure_instance_checks.py); the report counts the inserted points, and some object needs
# them. Squares stacked with a horizontal drift need many rounds (1/100: sewn, conforming;
# 1/5000: beyond the round cap, exit 1 naming the instance pair, no output). 3D: below.
# Reruns are byte-identical.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

inserted_total=0
for name in $("$BIN" example --list | grep -v $'\t3D ' | cut -f1); do
  case $name in mosfet) size=0.06 ;; aircraft) size=0.2 ;; bridge) size=0.03 ;; *) size=0.06 ;; esac
  "$BIN" example "$name" -o "$TMP/$name.json"
  area=$($PY tests/cli/geometry_area.py "$TMP/$name.json")
  if ! "$BIN" generate "$TMP/$name.json" --size "$size" --min-angle 25 --method merge \
      -o "$TMP/$name.vtu" --report "$TMP/$name.r.json" --quiet 2> "$TMP/err"; then
    fail "$name: --method merge failed"; sed 's/^/  | /' "$TMP/err"; continue; fi
  if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/$name.vtu" "$TMP/$name.r.json" "$area" 2>&1); then
    pass "$name (merge): $(echo "$msg" | tail -1)"; else fail "$name (merge): $msg"; fi
  n=$($PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['method'] == 'merge' and r['lemma_4_2_holds']; print(r['interface_merging']['points_inserted'])" "$TMP/$name.r.json") \
    || { fail "$name: report fields"; continue; }
  inserted_total=$((inserted_total + n))
done
[ "$inserted_total" -gt 0 ] && pass "Algorithm 5.3 inserted $inserted_total interface points over the objects" \
  || fail "no object needed an interface point: merge was never exercised"

"$BIN" generate "$TMP/mosfet.json" --size 0.06 --min-angle 25 --method merge -o "$TMP/again.vtu" --quiet
cmp -s "$TMP/again.vtu" "$TMP/mosfet.vtu" && pass "rerun: byte-identical" || fail "rerun differs"

drift() {
  cat > "$TMP/drift.json" <<JSON
{"symmesh": "templated-structure/1", "dimension": 2, "templates": [{"name": "square",
 "kind": "geometry", "vertices": [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]],
 "cells": [[0, 1, 2], [0, 2, 3]], "instances": [{"transformation": {"translation": ["0", "0"]}},
 {"transformation": {"translation": ["$1", "1"]}}, {"transformation": {"translation": ["0", "2"]}}]}]}
JSON
}
drift 1/100
if "$BIN" generate "$TMP/drift.json" --size 0.25 --method merge -o "$TMP/drift.vtu" \
    --report "$TMP/drift.r.json" --quiet; then
  if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/drift.vtu" "$TMP/drift.r.json" 3 2>&1); then
    pass "drift 1/100 sewn: $(echo "$msg" | tail -1)"; else fail "drift 1/100: $msg"; fi
  $PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['interface_merging']['rounds'] > 10, r['interface_merging']" \
    "$TMP/drift.r.json" && pass "drift 1/100 needed many rounds" || fail "drift 1/100 rounds"
else fail "drift 1/100: merge failed"; fi
drift 1/5000
expect_exit 1 "drift 1/5000 beyond the round cap" -- \
  "$BIN" generate "$TMP/drift.json" --size 0.25 --method merge -o "$TMP/drift5.vtu"
grep -q "the interface of instance . of template 'square' and instance . of template 'square'" \
  "$TMP/stderr" && [ ! -e "$TMP/drift5.vtu" ] && pass "the message names the pair; no output" \
  || fail "drift 1/5000 message: $(cat "$TMP/stderr")"

# 3D (spec/generation.md#merge-3d): the FinFET and the multi-TSV, whose faces are meshed in
# other frames than their partners, need Algorithm 5.2 merges and overlay points
# (Algorithms 5.3/5.4); certified (the independent meshio checks of every built-in 3D object
# are in test_generate_3d.sh); reruns byte-identical.
merged3=0 inserted3=0
for name in finfet multi-tsv; do
  "$BIN" example "$name" -o "$TMP/$name.json"
  if ! "$BIN" generate "$TMP/$name.json" --size 0.3 --method merge -o "$TMP/$name.vtu" \
      --report "$TMP/$name.r.json" --quiet 2> "$TMP/err"; then
    fail "$name: 3D --method merge failed"; sed 's/^/  | /' "$TMP/err"; continue; fi
  read -r m i < <($PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['method'] == 'merge' and r['lemma_4_2_holds']; x=r['interface_merging']; print(x['pairs_merged'], x['points_inserted'])" "$TMP/$name.r.json") \
    || { fail "$name: 3D report fields"; continue; }
  pass "$name (3D merge): certified, $m close pairs merged, $i overlay points"
  merged3=$((merged3 + m)); inserted3=$((inserted3 + i))
done
[ "$merged3" -gt 0 ] && [ "$inserted3" -gt 0 ] && pass "3D: Algorithm 5.2 and the overlay were both exercised" \
  || fail "3D: merges $merged3, overlay points $inserted3 (both must happen)"
"$BIN" generate "$TMP/finfet.json" --size 0.3 --method merge -o "$TMP/again3.vtu" --quiet
cmp -s "$TMP/again3.vtu" "$TMP/finfet.vtu" && pass "3D rerun: byte-identical" || fail "3D rerun differs"
finish
