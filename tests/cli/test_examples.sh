#!/usr/bin/env bash
# Built-in 2D geometries (spec/examples.md): every example is written, passes `symmesh check` as
# a templated geometry, and `symmesh generate` meshes it conformingly with the geometry's area
# (computed independently from the JSON by geometry_area.py), every triangle counter-clockwise,
# with the method auto picks and with bpp, conventional and gmsh; the symmetric ones are
# symmetric; bad names exit 2 with no file.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

# The 3D objects (summary "3D ...") are checked by test_generate_3d.sh.
names=$("$BIN" example --list | grep -v $'\t3D ' | cut -f1)
[ "$(echo "$names" | wc -l)" -ge 18 ] && pass "example --list names $(echo "$names" | wc -l) geometries" \
  || fail "example --list: $(echo "$names" | wc -l) names"

# example NAME SIZE: write, check, generate .vtu (with .tmesh) and .msh, verify both with meshio
# (cell count as reported, conforming, area) and open the .msh with gmsh.
example() {
  local name=$1 size=$2 geo="$TMP/$1.json"
  "$BIN" example "$name" -o "$geo" 2> "$TMP/err" || { fail "$name: example failed"; return; }
  if ! "$BIN" check "$geo" > "$TMP/check" 2> "$TMP/err"; then
    fail "$name: check failed"; sed 's/^/  | /' "$TMP/err" "$TMP/check" | tail -5; return; fi
  grep -q "templated geometry (Def 4.4): yes" "$TMP/check" || { fail "$name: not a templated geometry"; return; }
  local area ext
  area=$($PY tests/cli/geometry_area.py "$geo")
  for ext in vtu msh; do
    if ! "$BIN" generate "$geo" --size "$size" --min-angle 25 -o "$TMP/$name.$ext" \
        --templated "$TMP/$name.tmesh" --report "$TMP/$name.$ext.json" --quiet 2> "$TMP/err"; then
      fail "$name: generate .$ext failed"; sed 's/^/  | /' "$TMP/err"; return; fi
    if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/$name.$ext" "$TMP/$name.$ext.json" "$area" 2>&1); then
      pass "$name (.$ext): $(echo "$msg" | tail -1)"; else fail "$name (.$ext): $msg"; fi
  done
  cells=$($PY -c "import json,sys; print(json.load(open(sys.argv[1]))['cells_structure_instance'])" "$TMP/$name.msh.json")
  if gmsh -check "$TMP/$name.msh" > "$TMP/gmsh.out" 2>&1 && grep -q "Info *: $cells elements" "$TMP/gmsh.out"; then
    pass "$name: gmsh opens the .msh ($cells elements)"; else fail "$name: gmsh on the .msh"; tail -3 "$TMP/gmsh.out"; fi
  [ -s "$TMP/$name.tmesh" ] || fail "$name: no .tmesh written"
  # Every other method on the same object: the reader-side checks (conforming, every triangle
  # counter-clockwise, the area) hold for each (spec/outputs.md#orientation).
  local method
  for method in bpp conventional gmsh; do
    if ! "$BIN" generate "$geo" --size "$size" --min-angle 25 --method $method -o "$TMP/$name.$method.vtu" \
        --report "$TMP/$name.$method.json" --quiet 2> "$TMP/err"; then
      fail "$name: generate --method $method failed"; sed 's/^/  | /' "$TMP/err"; continue; fi
    if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/$name.$method.vtu" "$TMP/$name.$method.json" "$area" 2>&1); then
      pass "$name ($method): $(echo "$msg" | tail -1)"; else fail "$name ($method): $msg"; fi
  done
}

# Every built-in object, at a size that gives a few thousand triangles.
for name in $names; do
  case $name in
    mosfet) size=0.1 ;; aircraft) size=0.2 ;; bridge) size=0.03 ;; *) size=0.06 ;;
  esac
  example "$name" "$size"
done

# The symmetric objects' structure instances (method auto) map onto themselves under their
# symmetry: rotation by 2pi/n (n k), or the mirror x -> -x (0 0).
for case in "ngon-slice-5 5 1" "ngon-slice-8 8 3" "ngon-slice-16 16 1" "star-rotational 5 1" \
            "star-reflective-rotational 5 2" "mosfet 0 0" "aircraft 0 0"; do
  set -- $case
  if msg=$($PY tests/cli/symmetry_check.py "$TMP/$1.vtu" "$2" "$3" 2>&1); then
    pass "$1 under its symmetry ($2, $3): $msg"; else fail "$1 under its symmetry ($2, $3): $msg"; fi
done

expect_exit 2 "unknown example" -- "$BIN" example no-such-thing -o "$TMP/none.json"
grep -q "known: ngon-slice-5" "$TMP/stderr" && pass "the message lists the known names" || fail "message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/none.json" ] && pass "no file for an unknown example" || fail "file written for an unknown example"
# --templated without -o: only the templated mesh is written (a structure instance too large to
# write); neither -o nor --templated is bad input.
"$BIN" example ngon-slice-8 -o "$TMP/only.json"
"$BIN" generate "$TMP/only.json" --size 0.05 --templated "$TMP/only.tmesh" --quiet \
  && [ -s "$TMP/only.tmesh" ] && [ -z "$(ls "$TMP" | grep -E '^only\.(vtu|msh|mesh)$')" ] \
  && pass "--templated alone writes the .tmesh only" || fail "--templated alone"
expect_exit 2 "generate without -o and --templated" -- \
  "$BIN" generate "$TMP/only.json" --size 0.05
grep -q -- "--templated" "$TMP/stderr" || fail "the message names -o and --templated"
finish
