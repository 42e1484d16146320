#!/usr/bin/env bash
# symmesh generate (spec/generation.md): Algorithm 5.6 and the conventional baseline on built-in
# geometries over the rationals and K_m; outputs read back by meshio (cell count as reported,
# conforming, area of the geometry), the Gmsh baseline, .msh opened by gmsh, byte-identical
# reruns, and bad input refused with exit 2 and no file.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

# generate NAME FILE AREA METHOD EXT: generate, then check the written mesh independently.
generate() {
  local name=$1 file=$2 area=$3 method=$4 ext=$5 out="$TMP/$1.$5"
  if ! "$BIN" generate "$file" --size 0.08 --min-angle 25 --method "$method" -o "$out" \
      --report "$TMP/$name.json" 2> "$TMP/err"; then
    fail "$name: generate failed"; sed 's/^/  | /' "$TMP/err"; return; fi
  grep -q "symmesh generate: .*\[.* s\]" "$TMP/err" || fail "$name: no progress line on stderr"
  if msg=$($PY tests/cli/structure_instance_checks.py "$out" "$TMP/$name.json" "$area" 2>&1); then
    pass "$name ($method, .$ext): $(echo "$msg" | tail -1)"; else fail "$name: $msg"; fi
  $PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['lemma_4_2_holds'] and \
r['bytes_templated'] <= r['bytes_templated_svb_compact'] and r['min_angle_deg'] > 0, r" \
    "$TMP/$name.json" || fail "$name: report fields"
}

generate square data/square_geometry_2d.json 12 bpp vtu
generate rotational_slice data/fig_6_7_rotational_slice.json 24 bpp msh
generate irregular data/fig_4_11_irregular.json 2 bpp mesh
generate octagon data/ngon_slice_8.json 2.8284271247461907 bpp vtu
generate sao16 data/ngon_sao_16.json 3.0614674589207187 bpp msh
generate star data/star_5_half_slices.json 1.1225699414489640 bpp vtu
generate octagon_conventional data/ngon_slice_8.json 2.8284271247461907 conventional vtu
generate octagon_gmsh data/ngon_slice_8.json 2.8284271247461907 gmsh vtu
generate star_gmsh data/star_5_half_slices.json 1.1225699414489640 gmsh msh

# The templated mesh of the octagon is one slice: 8 instances share its triangles.
$PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['cells_structure_instance'] == \
8 * r['cells_templates'] and r['instances'] == 8, r" "$TMP/octagon.json" \
  && pass "octagon: 8 instances of one slice template" || fail "octagon: cell counts"

# The templated octagon and star meshes map onto themselves under their rotations (the SAO
# centre is meshed once, without symmetry, by this method).
for case in "octagon.vtu 8 1" "octagon.vtu 8 3" "star.vtu 5 1" "star.vtu 5 2"; do
  set -- $case
  if msg=$($PY tests/cli/symmetry_check.py "$TMP/$1" "$2" "$3" 2>&1); then
    pass "$1 under rotation 2pi*$3/$2: $msg"; else fail "$1 under rotation 2pi*$3/$2: $msg"; fi
done
# The conventional octagon is not built from copies, so it is not symmetric: the check can fail.
if $PY tests/cli/symmetry_check.py "$TMP/octagon_conventional.vtu" 8 1 > /dev/null 2>&1; then
  fail "the symmetry check accepts the conventional (unsymmetric) octagon"; else
  pass "the symmetry check rejects the conventional octagon"; fi

# The rotational method (Section 6.3, Algorithm 6.2: BPP of two copies) gives the same mesh as
# Algorithm 5.6 on a rotational slice structure, and refuses a structure that is not one.
generate octagon_rotational data/ngon_slice_8.json 2.8284271247461907 rotational vtu
cmp -s "$TMP/octagon_rotational.vtu" "$TMP/octagon.vtu" && pass "rotational octagon = bpp octagon, byte for byte" \
  || fail "rotational octagon differs from the bpp octagon"
"$BIN" example bridge -o "$TMP/bridge.json"
expect_exit 2 "rotational method on the bridge (translations)" -- "$BIN" generate "$TMP/bridge.json" --size 0.1 --method rotational -o "$TMP/bad6.vtu"
grep -q "not a rotational slice structure" "$TMP/stderr" && pass "message says why" || fail "message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/bad6.vtu" ] && pass "no file for a non-rotational structure" || fail "file written for a non-rotational structure"

# sao (Section 6.3.2, spec/generation.md#sao) with a 30° request: the 128-gon slice structure is
# cut into a centre 128-gon and a ring slice, the built-in SAO geometry is taken as cut; the line
# meshes are refined until every triangle meets the angle. Conforming, area of the 128-gon, and
# no triangle below 30° in the written mesh (meshio) and in the report.
AREA128=3.1403311569547525
for name in ngon-slice-128 ngon-sao-128; do
  "$BIN" example "$name" -o "$TMP/$name.json"
  if ! "$BIN" generate "$TMP/$name.json" --size 0.05 --min-angle 30 --method sao \
      -o "$TMP/$name-sao.vtu" --report "$TMP/$name-sao.json" 2> "$TMP/err"; then
    fail "$name: sao failed"; sed 's/^/  | /' "$TMP/err"; continue; fi
  if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/$name-sao.vtu" "$TMP/$name-sao.json" $AREA128 2>&1); then
    pass "$name (sao): $(echo "$msg" | tail -1)"; else fail "$name (sao): $msg"; fi
  if msg=$($PY - "$TMP/$name-sao.vtu" "$TMP/$name-sao.json" <<'PYEOF' 2>&1
import json, sys, math
import meshio, numpy as np
m = meshio.read(sys.argv[1]); r = json.load(open(sys.argv[2]))
tri = np.concatenate([c.data for c in m.cells if c.type == "triangle"])
p = m.points[:, :2][tri]
def angle(a, b, c):
    u, v = b - a, c - a
    return np.degrees(np.arctan2(np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]), (u * v).sum(1)))
smallest = np.minimum(np.minimum(angle(p[:, 0], p[:, 1], p[:, 2]), angle(p[:, 1], p[:, 2], p[:, 0])),
                      angle(p[:, 2], p[:, 0], p[:, 1])).min()
assert r["method"] == "sao" and r["lemma_4_2_holds"], r
assert r["quality"]["below_min_angle"] == 0 and r["min_angle_deg"] >= 30, r["min_angle_deg"]
assert smallest >= 30 - 1e-9, smallest
print(f"smallest angle {smallest:.2f} deg (meshio), report {r['min_angle_deg']:.2f}")
PYEOF
  ); then pass "$name (sao): $msg"; else fail "$name (sao, 30°): $msg"; fi
done
# Without sao the same request misses 30° near the boundaries (the reason sao refines them).
"$BIN" generate "$TMP/ngon-sao-128.json" --size 0.05 --min-angle 30 --method bpp -o "$TMP/sao-bpp.vtu" \
  --report "$TMP/sao-bpp.json" --quiet
$PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['quality']['below_min_angle'] > 0, r['min_angle_deg']" \
  "$TMP/sao-bpp.json" && pass "bpp alone misses 30° on the SAO 128-gon (the check can fail)" \
  || fail "bpp already meets 30° on the SAO 128-gon: the sao test shows nothing"

# sao where the request cannot be met: an input angle below it (the aircraft's 14.9° tail) is
# refused at once, and refinement that grades towards a 36° star tip without end stops after the
# face was made 32 times finer (it ran for minutes before); both exit 2 with no file, in seconds.
"$BIN" example aircraft -o "$TMP/aircraft.json"
"$BIN" example star -o "$TMP/star.json"
expect_exit 2 "sao with --min-angle above an input angle" -- timeout 60 "$BIN" generate "$TMP/aircraft.json" \
  --size 0.05 --min-angle 30 --method sao -o "$TMP/sao-air.vtu"
grep -q "template 'half' has an angle of 14.9" "$TMP/stderr" && [ "$(wc -l < "$TMP/stderr")" -eq 1 ] \
  && pass "the error names the template and its angle" || fail "error: $(cat "$TMP/stderr")"
expect_exit 2 "sao grading towards a 36° tip" -- timeout 60 "$BIN" generate "$TMP/star.json" --size 0.05 \
  --min-angle 30 --method sao -o "$TMP/sao-star.vtu"
grep -q "32 times finer.*36° at (1, 0)" "$TMP/stderr" && pass "the error names the segment and the tip" \
  || fail "error: $(cat "$TMP/stderr")"
[ ! -e "$TMP/sao-air.vtu" ] && [ ! -e "$TMP/sao-star.vtu" ] && pass "no file for an unmet sao request" \
  || fail "file written for an unmet sao request"
# At 25° the star converges; the rotated star's ring slice needed the split test to look at the
# constraint, not the edge (a split point rounded off its segment left the edge in place).
for name in star star-rotational; do
  "$BIN" example $name -o "$TMP/$name.json"
  if "$BIN" generate "$TMP/$name.json" --size 0.02 --min-angle 25 --method sao -o "$TMP/$name-sao.vtu" \
      --report "$TMP/$name-sao.json" --quiet 2> "$TMP/err" && \
     $PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['quality']['below_min_angle'] == 0 \
and r['min_angle_deg'] >= 25, r['min_angle_deg']" "$TMP/$name-sao.json"; then
    pass "$name: sao meets 25°"; else fail "$name: sao at 25°: $(cat "$TMP/err")"; fi
done

# Reflective (Algorithms 6.1/6.4) and reflective-rotational (Algorithm 6.5) methods: conforming,
# the geometry's area, and the mesh maps onto itself under the mirror / the rotation.
"$BIN" example mosfet -o "$TMP/mosfet.json"
"$BIN" example star-reflective-rotational -o "$TMP/srr.json"
generate mosfet_reflective "$TMP/mosfet.json" "$($PY tests/cli/geometry_area.py "$TMP/mosfet.json")" reflective vtu
generate star_combined "$TMP/srr.json" "$($PY tests/cli/geometry_area.py "$TMP/srr.json")" combined msh
generate plus_reflective tests/data/orthogonal_reflections_2d.json 20 reflective vtu
for case in "mosfet_reflective.vtu 0 0" "star_combined.msh 5 1" "star_combined.msh 5 2" \
            "plus_reflective.vtu 0 0" "plus_reflective.vtu 2 1"; do
  set -- $case
  if msg=$($PY tests/cli/symmetry_check.py "$TMP/$1" "$2" "$3" 2>&1); then
    pass "$1 under its symmetry ($2, $3): $(echo "$msg" | tail -1)"; else fail "$1 under its symmetry ($2, $3): $msg"; fi
done
$PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['method'] == 'combined' and r['instances'] == 10, r" \
  "$TMP/star_combined.json" && pass "star: 10 copies of one half-slice (combined)" || fail "star: report"
expect_exit 2 "reflective method on the octagon slices (rotations)" -- "$BIN" generate data/ngon_slice_8.json --size 0.1 --method reflective -o "$TMP/bad8.vtu"
grep -q "not a reflective structure" "$TMP/stderr" && pass "message says why" || fail "message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/bad8.vtu" ] && pass "no file for a non-reflective structure" || fail "file written for a non-reflective structure"
expect_exit 2 "combined method on the MOSFET (one mirror, no rotation)" -- "$BIN" generate "$TMP/mosfet.json" --size 0.1 --method combined -o "$TMP/bad9.vtu"

# gmsh opens every .msh written, with as many elements as the report says and no duplicates.
for name in rotational_slice sao16 star_gmsh; do
  cells=$($PY -c "import json,sys; print(json.load(open(sys.argv[1]))['cells_structure_instance'])" "$TMP/$name.json")
  if gmsh -check "$TMP/$name.msh" > "$TMP/gmsh.out" 2>&1 && grep -q "Info *: $cells elements" "$TMP/gmsh.out" && \
     ! grep -qiE "error|duplicate (nodes|elements) found|warning" "$TMP/gmsh.out"; then
    pass "gmsh opens $name.msh: $cells elements, no duplicates"; else
    fail "gmsh on $name.msh"; sed 's/^/  | /' "$TMP/gmsh.out" | tail -5; fi
done

# Determinism: the same input and options give the same bytes.
"$BIN" generate data/ngon_sao_16.json --size 0.08 --min-angle 25 -o "$TMP/again.msh" --quiet
cmp -s "$TMP/again.msh" "$TMP/sao16.msh" && pass "rerun is byte-identical" || fail "rerun differs"

# Bad input: exit 2, one line naming the problem, no output file.
expect_exit 2 "negative size" -- "$BIN" generate data/ngon_slice_8.json --size -1 -o "$TMP/bad1.vtu"
[ ! -e "$TMP/bad1.vtu" ] && pass "no file for a negative size" || fail "file written for a negative size"
expect_exit 2 "unknown extension" -- "$BIN" generate data/ngon_slice_8.json --size 0.1 -o "$TMP/bad.obj"
expect_exit 2 "mesh templates instead of a geometry" -- "$BIN" generate data/fig_4_3_templated_mesh.json --size 0.1 -o "$TMP/bad2.vtu"
grep -q "geometry templates" "$TMP/stderr" && pass "message names the template kind" || fail "message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/bad2.vtu" ] && pass "no file for mesh templates" || fail "file written for mesh templates"
expect_exit 2 "overlapping instances" -- "$BIN" generate tests/data/bad/overlapping_instances.json --size 0.1 -o "$TMP/bad3.vtu"
expect_exit 2 "unknown method" -- "$BIN" generate data/ngon_slice_8.json --size 0.1 --method frobnicate -o "$TMP/bad4.vtu"
grep -q "frobnicate" "$TMP/stderr" && pass "message names the method" || fail "message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/bad4.vtu" ] && pass "no file for an unknown method" || fail "file written for an unknown method"
expect_exit 2 "malformed JSON" -- "$BIN" generate tests/data/bad/malformed.json --size 0.1 -o "$TMP/bad5.vtu"
for bad in open_polygon:"repeated vertex" self_intersecting_polygon:"self-intersecting"; do
  file=${bad%%:*} what=${bad#*:}
  expect_exit 2 "$file" -- "$BIN" generate "tests/data/bad/$file.json" --size 0.1 -o "$TMP/$file.vtu"
  grep -q "templates\[0\].polygon.*$what" "$TMP/stderr" && pass "$file: the message names the polygon" \
    || fail "$file: message $(cat "$TMP/stderr")"
  [ ! -e "$TMP/$file.vtu" ] && pass "$file: no file written" || fail "$file: file written"
done
finish
