#!/usr/bin/env bash
# symmesh cut (spec/generation.md#cut): a whole symmetric object is cut into the piece of
# Algorithm 6.2 (first ray by Algorithm 6.3), 6.1, 6.4 or 6.5; the piece is read back, meshed by
# the matching symmetric method, and the structure instance is conforming, has the whole
# object's area (computed from the whole object's JSON) and maps onto itself under the symmetry.
# Bad symmetries and options exit 2 with one line and no file; the output is deterministic.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

# cut_and_mesh NAME WHOLE METHOD SIZE SYMMETRY(n k for symmetry_check.py) -- cut options...
cut_and_mesh() {
  local name=$1 whole=$2 method=$3 size=$4 n=$5 k=$6; shift 7
  if ! "$BIN" cut "$TMP/$whole.json" "$@" -o "$TMP/$name.json" --report "$TMP/$name.cut.json" \
      2> "$TMP/err"; then fail "$name: cut failed"; sed 's/^/  | /' "$TMP/err"; return; fi
  pass "$name: $(tail -1 "$TMP/err")"
  "$BIN" check "$TMP/$name.json" > "$TMP/check" 2>&1 && grep -q "templated geometry (Def 4.4): yes" "$TMP/check" \
    && pass "$name: the piece is a templated geometry" || fail "$name: check of the piece"
  if ! "$BIN" generate "$TMP/$name.json" --size "$size" --min-angle 25 --method "$method" \
      -o "$TMP/$name.vtu" --report "$TMP/$name.r.json" --quiet 2> "$TMP/err"; then
    fail "$name: generate --method $method failed"; sed 's/^/  | /' "$TMP/err"; return; fi
  local area
  area=$($PY tests/cli/geometry_area.py "$TMP/$whole.json")
  if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/$name.vtu" "$TMP/$name.r.json" "$area" 2>&1); then
    pass "$name (--method $method): $(echo "$msg" | tail -1)"; else fail "$name: $msg"; fi
  if msg=$($PY tests/cli/symmetry_check.py "$TMP/$name.vtu" "$n" "$k" 2>&1); then
    pass "$name: symmetric under ($n, $k)"; else fail "$name: $msg"; fi
}

for e in ngon-8 gear star mosfet aircraft; do "$BIN" example "$e" -o "$TMP/$e.json"; done

cut_and_mesh octagon ngon-8 rotational 0.05 8 1 -- --rotation 8
cut_and_mesh gear_slice gear rotational 0.04 12 1 -- --rotation 12
cut_and_mesh star_slice star rotational 0.05 5 1 -- --rotation 5
cut_and_mesh star_half_slice star combined 0.05 5 1 -- --rotation 5 --mirror 0,1
cut_and_mesh mosfet_half mosfet reflective 0.1 0 0 -- --mirror 1,0
cut_and_mesh aircraft_half aircraft reflective 0.2 0 0 -- --mirror 1,0

# Algorithm 6.3 on the gear: the first ray runs through the middle of a tooth (90°), where the
# x-axis would cross a flank at about 30°.
if $PY - "$TMP/gear_slice.cut.json" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
assert abs(r["start_angle_deg"] - 7.5) < 1e-9, r
assert abs(r["smallest_new_angle_deg"] - 90) < 1e-9, r
assert 30 < r["smallest_new_angle_at_x_axis_deg"] < 31, r
EOF
then pass "gear: Algorithm 6.3 starts at 7.5 deg (90 deg, x-axis about 30 deg)"; else fail "gear: Algorithm 6.3 report"; fi

# A given first ray (--start) is kept: the x-axis crosses the gear's flank at about 30.5°.
"$BIN" cut "$TMP/gear.json" --rotation 12 --start 1,0 -o "$TMP/gear_x.json" --report "$TMP/gear_x.cut.json" --quiet
if $PY - "$TMP/gear_x.cut.json" <<'EOF'
import json, sys
r = json.load(open(sys.argv[1]))
assert r["start_kind"] == "given" and abs(r["start_angle_deg"]) < 1e-9, r
assert 30 < r["smallest_new_angle_deg"] < 31, r
EOF
then pass "gear --start 1,0: the given ray is kept"; else fail "gear --start 1,0"; fi

# Two orthogonal mirrors (Algorithm 6.4) on the octagon, whose mirrors include both axes.
cut_and_mesh octagon_quadrant ngon-8 reflective 0.05 0 0 -- --mirror 1,0 --mirror 0,1

# Two regions (an inner octagon and the ring around it) cut by the rotation give two templates,
# each instanced by the 8 rotations: the rotational method (copy 0 against copies k <= n/2)
# and the bpp method (all pairs) must write the same mesh.
$PY - "$TMP/rings.json" <<'EOF'
import json, sys
ring = lambda r: [[f"{r}*cos(2pi*{k}/8)", f"{r}*sin(2pi*{k}/8)"] for k in range(8)]
doc = {"symmesh": "templated-structure/1", "dimension": 2, "templates": [
    {"name": "inner", "kind": "geometry", "polygon": ring("1/2"),
     "instances": [{"transformation": {"identity": {}}, "region": 1}]},
    {"name": "outer", "kind": "geometry", "polygon": ring("1"), "holes": [ring("1/2")],
     "instances": [{"transformation": {"identity": {}}, "region": 2}]}]}
json.dump(doc, open(sys.argv[1], "w"))
EOF
if "$BIN" cut "$TMP/rings.json" --rotation 8 -o "$TMP/rings_slice.json" --quiet \
   && [ "$($PY -c "import json,sys; print(len(json.load(open(sys.argv[1]))['templates']))" "$TMP/rings_slice.json")" = 2 ] \
   && "$BIN" generate "$TMP/rings_slice.json" --size 0.05 --method rotational -o "$TMP/rings_rot.vtu" --quiet \
   && "$BIN" generate "$TMP/rings_slice.json" --size 0.05 --method bpp -o "$TMP/rings_bpp.vtu" --quiet \
   && cmp -s "$TMP/rings_rot.vtu" "$TMP/rings_bpp.vtu"; then
  pass "two-region slice: rotational and bpp meshes are byte-identical"
else fail "two-region slice: rotational vs bpp"; fi

# --method auto runs the specialised method the piece admits (checked exactly).
for pair in octagon:rotational star_half_slice:combined mosfet_half:reflective octagon_quadrant:reflective; do
  piece=${pair%%:*} want=${pair#*:}
  "$BIN" generate "$TMP/$piece.json" --size 0.1 -o "$TMP/auto.vtu" --report "$TMP/auto.json" --quiet \
    && got=$($PY -c "import json,sys; print(json.load(open(sys.argv[1]))['method'])" "$TMP/auto.json") \
    && [ "$got" = "$want" ] && pass "auto on $piece runs $want" || fail "auto on $piece: ${got:-failed}, expected $want"
done

# Deterministic: the same cut twice is byte-identical.
"$BIN" cut "$TMP/gear.json" --rotation 12 -o "$TMP/gear_again.json" --quiet
"$BIN" cut "$TMP/gear.json" --rotation 12 -o "$TMP/gear_third.json" --quiet
cmp -s "$TMP/gear_again.json" "$TMP/gear_third.json" && pass "cut output is deterministic" \
  || fail "two cuts of the gear differ"

# Bad input: exit 2, one line naming the problem, no file.
bad() {
  local what=$1 pattern=$2; shift 2
  rm -f "$TMP/bad.json"
  expect_exit 2 "$what" -- "$BIN" cut "$@" -o "$TMP/bad.json"
  [ "$(wc -l < "$TMP/stderr")" -eq 1 ] && grep -q -- "$pattern" "$TMP/stderr" \
    && pass "$what: message names it" || fail "$what: message: $(cat "$TMP/stderr")"
  [ ! -e "$TMP/bad.json" ] && pass "$what: no file written" || fail "$what: a file was written"
}
bad "star has no order-4 rotation" "maps the boundary segment" "$TMP/star.json" --rotation 4
bad "aircraft has no mirror y = 0" "region 1" "$TMP/aircraft.json" --mirror 0,1
bad "mirrors not orthogonal" "not orthogonal" "$TMP/ngon-8.json" --mirror 1,0 --mirror 1,1
bad "rotation order 1" "at least 2" "$TMP/ngon-8.json" --rotation 1
bad "rotation order too large" "at most" "$TMP/ngon-8.json" --rotation 999983
bad "no symmetry given" "rotation order or a mirror" "$TMP/ngon-8.json"
bad "malformed mirror" "--mirror" "$TMP/ngon-8.json" --mirror 1
bad "NaN in a mirror" "--mirror" "$TMP/ngon-8.json" --mirror nan,1
bad "unknown option" "--frobnicate" "$TMP/ngon-8.json" --rotation 8 --frobnicate
bad "start with a mirror" "--start" "$TMP/star.json" --rotation 5 --mirror 0,1 --start 1,0
# 3D (spec/generation.md#cut-3d): the whole 8-TSV (three annulus prisms given as PLCs) cut into
# slices about the z axis and into half-slices (Algorithm 6.5), the FinFET into its quadrant
# (Algorithm 6.4); each cut meshed by the method auto picks, read back by meshio: conforming,
# positive, the whole object's volume and boundary area.
"$BIN" example tsv-whole-8 -o "$TMP/tsv_whole.json"
"$BIN" example finfet -o "$TMP/finfet.json"
read -r TSV_VOLUME TSV_SURFACE < <(/usr/bin/python3 -c "
import math
n, h, R, r = 8, 2.0, 1.0, 0.2
area = lambda q: n / 2 * q * q * math.sin(2 * math.pi / n)
perimeter = lambda q: 2 * n * q * math.sin(math.pi / n)
print(h * (area(R) - area(r)), 2 * (area(R) - area(r)) + h * (perimeter(R) + perimeter(r)))")
cut3() { # NAME INPUT METHOD VOLUME SURFACE CUT-OPTIONS...
  local name=$1 input=$2 method=$3 volume=$4 surface=$5; shift 5
  if ! "$BIN" cut "$input" "$@" -o "$TMP/$name.json" --quiet 2> "$TMP/err"; then
    fail "$name: cut failed: $(cat "$TMP/err")"; return; fi
  if ! "$BIN" generate "$TMP/$name.json" --size 0.15 -o "$TMP/$name.vtu" --report "$TMP/$name.r.json" \
      --quiet 2> "$TMP/err"; then fail "$name: generate failed: $(cat "$TMP/err")"; return; fi
  /usr/bin/python3 -c "import json,sys; m=json.load(open(sys.argv[1]))['method']; assert m == sys.argv[2], m" \
    "$TMP/$name.r.json" "$method" || fail "$name: auto did not pick $method"
  if msg=$(/usr/bin/python3 tests/cli/structure_instance_checks.py "$TMP/$name.vtu" "$TMP/$name.r.json" \
      "$volume" "$surface" 2>&1); then pass "$name: cut + $method: $(echo "$msg" | tail -1)"
  else fail "$name: $msg"; fi
}
cut3 tsv_slices "$TMP/tsv_whole.json" rotational "$TSV_VOLUME" "$TSV_SURFACE" --rotation 8
cut3 tsv_half_slices "$TMP/tsv_whole.json" combined "$TSV_VOLUME" "$TSV_SURFACE" --rotation 8 --mirror 0,1,0
cut3 finfet_quadrant "$TMP/finfet.json" reflective 14.48 46.4 --mirror 1,0,0 --mirror 0,1,0
bad "3D: the TSV has no order-16 rotation" "does not have the symmetry" "$TMP/tsv_whole.json" --rotation 16
bad "3D: the FinFET has no mirror z = 0" "region 1" "$TMP/finfet.json" --mirror 0,0,1
bad "3D: a mirror with a rotation must contain the axis" "contain" "$TMP/tsv_whole.json" --rotation 8 --mirror 0,1,1
bad "3D: mirror needs three components" "--mirror" "$TMP/finfet.json" --mirror 1,0
bad "3D: mirror planes not orthogonal" "not orthogonal" "$TMP/finfet.json" --mirror 1,0,0 --mirror 1,1,0
echo '{"symmesh": "templated-structure/1", "dimension": 2, "templates": [' > "$TMP/broken.json"
bad "malformed JSON" "broken.json" "$TMP/broken.json" --rotation 4
finish
