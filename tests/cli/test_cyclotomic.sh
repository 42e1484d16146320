#!/usr/bin/env bash
# Exact kernels of every symmetry order (spec/number-type.md#kernel-choice): symmesh check picks
# the rational kernel or K_m and names it; the built-in n-gon, SAO and star geometries are valid
# templated geometries; bpp draws K_m structures; bad symbolic input fails with one line, exit 2.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

# check_geometry FILE M: valid templated geometry, kernel K_M named in text and JSON.
check_geometry() {
  local file=$1 m=$2 name start end
  name=$(basename "$file")
  start=$(date +%s%N)
  if ! "$BIN" check "$file" > "$TMP/out" 2> "$TMP/err"; then
    fail "$name: check failed"; sed 's/^/  | /' "$TMP/err"; return; fi
  end=$(date +%s%N)
  grep -q "kernel K_$m = Q(cos 2pi/$m)" "$TMP/out" || { fail "$name: kernel K_$m not named"; return; }
  grep -q "templated geometry (Def 4.4): yes" "$TMP/out" || { fail "$name: not a templated geometry"; return; }
  "$BIN" check --json "$file" > "$TMP/json" 2> "$TMP/err"
  $PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['field_m']==$m and r['templated_geometry'], r" \
    "$TMP/json" || { fail "$name: check --json"; return; }
  pass "$name: templated geometry in K_$m ($(( (end - start) / 1000000 )) ms)"
}

check_geometry data/star_5_half_slices.json 20
for n in 5 8 16 32 64 128; do
  m=$(( n % 4 == 0 ? n : 4 * n ))
  check_geometry data/ngon_slice_$n.json $m
  check_geometry data/ngon_sao_$n.json $m
done

# The rational kernel stays the default when every order is 1, 2 or 4.
expect_exit 0 "order-4 rotations stay rational" -- "$BIN" check data/fig_6_7_rotational_slice.json
grep -q "kernel rational" "$TMP/stdout" && pass "rational kernel named" || fail "rational kernel not named"

# bpp on a K_m structure: SVG and JSON, deterministic.
expect_exit 0 "bpp of the star (SVG)" -- "$BIN" bpp data/star_5_half_slices.json -o "$TMP/star.svg" --quiet
grep -q "<svg" "$TMP/star.svg" && pass "star SVG written" || fail "star SVG missing"
"$BIN" bpp data/ngon_slice_8.json --json --quiet > "$TMP/a.json" 2>/dev/null
"$BIN" bpp data/ngon_slice_8.json --json --quiet > "$TMP/b.json" 2>/dev/null
cmp -s "$TMP/a.json" "$TMP/b.json" && pass "bpp --json deterministic in K_8" || fail "bpp --json differs"

# Bad symbolic input: one line naming the field, exit 2, no output file.
doc() { # doc TRANSFORMATION [VERTEX_X]
  printf '{"symmesh": "templated-structure/1", "dimension": 2, "templates": [{"kind": "geometry", "polygon": [["0","0"],["1","0"],["%s","1"]], "instances": [{"transformation": %s}]}]}' "${2:-0}" "$1"
}
bad() { # bad DESCRIPTION EXPECTED_TEXT JSON
  printf '%s' "$3" > "$TMP/bad.json"
  expect_exit 2 "$1" -- "$BIN" check "$TMP/bad.json"
  [ "$(wc -l < "$TMP/stderr")" -eq 1 ] || fail "$1: message is not one line"
  grep -q -- "$2" "$TMP/stderr" || { fail "$1: message lacks '$2'"; sed 's/^/  | /' "$TMP/stderr"; }
}
bad "orders beyond K_1024" "templates\[0\].instances\[0\].transformation.compose\[2\].rotation.order" \
  "$(doc '{"compose": [{"rotation": {"order": 7}}, {"rotation": {"order": 9, "k": 2}}, {"rotation": {"order": 11}}]}')"
bad "zero order" "rotation.order" "$(doc '{"rotation": {"order": 0}}')"
bad "division by zero" "divides by zero" "$(doc '{"identity": {}}' '1/(cos(2pi*1/4))')"
bad "unknown function" "is not an exact number" "$(doc '{"identity": {}}' 'tan(2pi*1/8)')"
bad "wrong K literal degree" "K8 has degree 2" "$(doc '{"identity": {}}' 'K8[1, 2, 3]')"
bad "NaN" "NaN" "$(doc '{"identity": {}}' 'nan')"
expect_exit 2 "bpp: bad input writes no file" -- "$BIN" bpp "$TMP/bad.json" -o "$TMP/none.svg"
[ ! -e "$TMP/none.svg" ] && pass "no partial output" || fail "partial output written"
finish
