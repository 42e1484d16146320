#!/usr/bin/env bash
# symmesh generate on 3D templated geometries (spec/generation.md#alg-5-7): Algorithm 5.7 (bpp)
# and the conventional baseline (TetGen on the regions of AT), written as binary .vtu, .msh and
# .mesh, read back by meshio (cell count as reported, every triangle in at most two tetrahedra,
# closed boundary, boundary area of the union (a non-conforming interface would add to it), no
# duplicate vertex, positive volumes, exact volume), .msh opened by gmsh, byte-identical reruns,
# the cell estimate refusing an infeasible --size, and a 3D method that does not exist yet
# refused with exit 2 and no file.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

# generate NAME FILE VOLUME SURFACE METHOD EXT
generate() {
  local name=$1 file=$2 volume=$3 surface=$4 method=$5 ext=$6 out="$TMP/$1.$6"
  if ! "$BIN" generate "$file" --size 0.15 --method "$method" -o "$out" \
      --report "$TMP/$name.json" 2> "$TMP/err"; then
    fail "$name: generate failed"; sed 's/^/  | /' "$TMP/err"; return; fi
  grep -q "symmesh generate: .*\[.* s\]" "$TMP/err" || fail "$name: no progress line on stderr"
  if msg=$($PY tests/cli/structure_instance_checks.py "$out" "$TMP/$name.json" "$volume" "$surface" 2>&1); then
    pass "$name ($method, .$ext): $(echo "$msg" | tail -1)"; else fail "$name: $msg"; fi
  $PY -c "import json,sys; r=json.load(open(sys.argv[1])); q=r['quality']; \
assert r['lemma_4_2_holds'] and q['tetrahedra'] == r['cells_structure_instance'] and r['seconds_breakdown']['lemma_4_2_certificate'] < r['seconds_breakdown']['template_meshing'] + 0.05 and \
0 < q['min_dihedral_deg'] < 70.6 < q['max_dihedral_deg'] < 180 and q['max_radius_edge_ratio'] > 0.6, r" \
    "$TMP/$name.json" || fail "$name: report fields"
}

generate halves data/cube_mirrored_halves_3d.json 2 10 bpp vtu
generate halves_msh data/cube_mirrored_halves_3d.json 2 10 bpp msh
generate slices data/rotational_slice_3d.json 4 16 bpp vtu
generate slices_mesh data/rotational_slice_3d.json 4 16 auto mesh
generate slices_conventional data/rotational_slice_3d.json 4 16 conventional vtu

# Only the templates are meshed: the four slices cost one slice's tetrahedra.
$PY -c "import json,sys; r=json.load(open(sys.argv[1])); c=json.load(open(sys.argv[2])); \
assert r['cells_structure_instance'] == 4 * r['cells_templates'], r; \
assert r['bytes_templated_svb_compact'] * 3 < c['bytes_templated_svb_compact'], (r, c)" \
  "$TMP/slices.json" "$TMP/slices_conventional.json" \
  && pass "slices: the templated mesh stores one of four slices" || fail "slices: template bytes"

if gmsh -check "$TMP/halves_msh.msh" > "$TMP/gmsh.log" 2>&1 && grep -qi "tetrahedra\|elements" "$TMP/gmsh.log"; then
  pass "gmsh opens the 3D .msh"; else fail "gmsh -check on the 3D .msh"; sed 's/^/  | /' "$TMP/gmsh.log" | tail -5; fi

"$BIN" generate data/rotational_slice_3d.json --size 0.15 -o "$TMP/again.vtu" --quiet \
  && cmp -s "$TMP/slices.vtu" "$TMP/again.vtu" && pass "3D rerun is byte-identical" \
  || fail "3D rerun differs"

expect_exit 2 "--size 1e-4 in 3D is refused by the cell estimate" -- \
  "$BIN" generate data/rotational_slice_3d.json --size 1e-4 -o "$TMP/huge.vtu"
grep -q "tetrahedra (volume 4" "$TMP/stderr" || fail "the refusal states the tetrahedra and volume"
[ ! -e "$TMP/huge.vtu" ] || fail "a refused 3D run left a file"
expect_exit 2 "--method rotational in 3D is refused (not implemented yet)" -- \
  "$BIN" generate data/rotational_slice_3d.json --size 0.15 --method rotational -o "$TMP/rot.vtu"
[ ! -e "$TMP/rot.vtu" ] || fail "a refused 3D method left a file"
expect_exit 2 "3D mesh templates are refused (Algorithm 5.7 needs geometry templates)" -- \
  "$BIN" generate data/reflected_cube_3d.json --size 0.15 -o "$TMP/mt.vtu"
finish
