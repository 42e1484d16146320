#!/usr/bin/env bash
# Built-in 2D geometries (spec/examples.md): every example is written, passes `symmesh check` as
# a templated geometry, and `symmesh generate` meshes it conformingly with the geometry's area
# (computed independently from the JSON by geometry_area.py); bad names exit 2 with no file.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

names=$("$BIN" example --list | cut -f1)
[ "$(echo "$names" | wc -l)" -ge 18 ] && pass "example --list names $(echo "$names" | wc -l) geometries" \
  || fail "example --list: $(echo "$names" | wc -l) names"

# example NAME SIZE: write, check, generate, verify.
example() {
  local name=$1 size=$2 geo="$TMP/$1.json"
  "$BIN" example "$name" -o "$geo" 2> "$TMP/err" || { fail "$name: example failed"; return; }
  if ! "$BIN" check "$geo" > "$TMP/check" 2> "$TMP/err"; then
    fail "$name: check failed"; sed 's/^/  | /' "$TMP/err" "$TMP/check" | tail -5; return; fi
  grep -q "templated geometry (Def 4.4): yes" "$TMP/check" || { fail "$name: not a templated geometry"; return; }
  if ! "$BIN" generate "$geo" --size "$size" --min-angle 25 -o "$TMP/$name.vtu" \
      --templated "$TMP/$name.tmesh" --report "$TMP/$name.report.json" --quiet 2> "$TMP/err"; then
    fail "$name: generate failed"; sed 's/^/  | /' "$TMP/err"; return; fi
  local area
  area=$($PY tests/cli/geometry_area.py "$geo")
  if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/$name.vtu" "$TMP/$name.report.json" "$area" 2>&1); then
    pass "$name: $msg"; else fail "$name: $msg"; fi
  [ -s "$TMP/$name.tmesh" ] || fail "$name: no .tmesh written"
}

example ngon-slice-16 0.05
example ngon-sao-32 0.05
example mosfet 0.1
example aircraft 0.2
example bridge 0.02
example star 0.05
example star-rotational 0.05
example star-reflective-rotational 0.05

expect_exit 2 "unknown example" -- "$BIN" example no-such-thing -o "$TMP/none.json"
grep -q "known: ngon-slice-5" "$TMP/stderr" && pass "the message lists the known names" || fail "message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/none.json" ] && pass "no file for an unknown example" || fail "file written for an unknown example"
finish
