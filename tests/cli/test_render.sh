#!/usr/bin/env bash
# symmesh render: every built-in 2D example renders (SVG polygons = cells of the report, PNG of
# the SVG's size), the 3D multiblock has one block per template and reads back in VTK, bad
# inputs exit 2 without an output file, and the same input gives the same bytes.
source "$(dirname "$0")/common.sh" "$@"

# svg_check SVG CELLS: well-formed XML whose cell polygons number CELLS; prints "W H" on success.
svg_check() {
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
ns = "{http://www.w3.org/2000/svg}"
polygons = len(root.findall(f".//{ns}polygon"))
if polygons != int(sys.argv[2]):
    sys.exit(f"{polygons} polygons, want {sys.argv[2]}")
print(int(float(root.get("width"))), int(float(root.get("height"))))
PY
}

# png_size PNG: "W H" from the IHDR chunk after checking the PNG signature.
png_size() {
  /usr/bin/python3 - "$1" <<'PY'
import struct, sys
b = open(sys.argv[1], "rb").read(24)
if b[:8] != b"\x89PNG\r\n\x1a\n":
    sys.exit("not a PNG")
print(*struct.unpack(">II", b[16:24]))
PY
}

report_value() { /usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))[sys.argv[2]])" "$1" "$2"; }

colours=(template instance region quality)
k=0
for name in $("$BIN" example --list | cut -f1); do
  "$BIN" example "$name" -o "$TMP/$name.json" 2> /dev/null || { fail "example $name"; continue; }
  dim=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1])).get('dimension', 2))" "$TMP/$name.json")
  [ "$dim" = 2 ] || continue
  if ! "$BIN" generate "$TMP/$name.json" --size 0.1 --templated "$TMP/$name.tmesh" \
      --report "$TMP/$name.report.json" --quiet 2> "$TMP/stderr"; then
    fail "generate $name"; sed 's/^/  | /' "$TMP/stderr"; continue
  fi
  cells=$(report_value "$TMP/$name.report.json" cells_structure_instance)
  colour=${colours[$((k % 4))]}
  k=$((k + 1))
  "$BIN" render "$TMP/$name.tmesh" --color "$colour" -o "$TMP/$name.svg" --quiet 2> "$TMP/stderr" \
    || { fail "render $name --color $colour"; sed 's/^/  | /' "$TMP/stderr"; continue; }
  if size=$(svg_check "$TMP/$name.svg" "$cells" 2>&1); then
    pass "$name --color $colour: valid SVG with $cells cell polygons ($size px)"
  else fail "$name: $size"; continue; fi
  "$BIN" render "$TMP/$name.tmesh" --color "$colour" -o "$TMP/$name.png" --quiet \
    || { fail "render $name .png"; continue; }
  png=$(png_size "$TMP/$name.png" 2>&1)
  [ "$png" = "$size" ] && pass "$name: PNG signature, $png px = the SVG's" \
    || fail "$name: PNG is '$png', SVG is '$size'"
done
[ "$k" -ge 20 ] && pass "$k built-in 2D examples rendered" || fail "only $k built-in 2D examples"

# Every colouring of one mesh: same polygons, different fills; quality has its colour bar.
cells=$(report_value "$TMP/bridge.report.json" cells_structure_instance)
for c in "${colours[@]}"; do
  "$BIN" render "$TMP/bridge.tmesh" --color "$c" -o "$TMP/bridge.$c.svg" --quiet
  svg_check "$TMP/bridge.$c.svg" "$cells" > /dev/null && pass "bridge --color $c" || fail "bridge --color $c"
done
grep -q 'class="colour-bar"' "$TMP/bridge.quality.svg" && pass "quality has a colour bar" \
  || fail "quality has no colour bar"
cmp -s "$TMP/bridge.template.svg" "$TMP/bridge.instance.svg" && fail "template and instance colourings agree" \
  || pass "template and instance colourings differ"
grep -q 'class="interfaces"' "$TMP/bridge.template.svg" && grep -q 'class="boundary"' "$TMP/bridge.template.svg" \
  && pass "interfaces and boundary drawn" || fail "interfaces or boundary missing"

# Determinism: the same input gives the same bytes (SVG and PNG).
"$BIN" render "$TMP/bridge.tmesh" --color quality -o "$TMP/again.svg" --quiet
cmp -s "$TMP/bridge.quality.svg" "$TMP/again.svg" && pass "SVG deterministic" || fail "SVG differs between runs"
"$BIN" render "$TMP/bridge.tmesh" --color quality -o "$TMP/a.png" --quiet
"$BIN" render "$TMP/bridge.tmesh" --color quality -o "$TMP/b.png" --quiet
cmp -s "$TMP/a.png" "$TMP/b.png" && pass "PNG deterministic" || fail "PNG differs between runs"
# Progress line unless --quiet.
"$BIN" render "$TMP/bridge.tmesh" -o "$TMP/p.svg" 2> "$TMP/stderr"
grep -q "symmesh render: wrote" "$TMP/stderr" && pass "progress line on stderr" || fail "no progress line"

# 3D: a multiblock with one block per template, read back by VTK; a boundary-surface picture.
"$BIN" example tsv-8 -o "$TMP/tsv.json"
"$BIN" generate "$TMP/tsv.json" --size 0.15 --templated "$TMP/tsv.tmesh" --report "$TMP/tsv.report.json" --quiet
templates=$(report_value "$TMP/tsv.report.json" templates)
cells=$(report_value "$TMP/tsv.report.json" cells_structure_instance)
expect_exit 0 "render 3D .vtm" -- "$BIN" render "$TMP/tsv.tmesh" -o "$TMP/tsv.vtm"
blocks=$(grep -c '<DataSet ' "$TMP/tsv.vtm")
[ "$blocks" -eq "$templates" ] && pass ".vtm lists $blocks blocks = templates" || fail ".vtm lists $blocks blocks, want $templates"
read_cells=$(/usr/bin/python3 - "$TMP/tsv.vtm" <<'PY' 2>&1
import sys, vtk
r = vtk.vtkXMLMultiBlockDataReader()
r.SetFileName(sys.argv[1])
r.Update()
out = r.GetOutput()
n, templates = 0, set()
for b in range(out.GetNumberOfBlocks()):
    g = out.GetBlock(b)
    n += g.GetNumberOfCells()
    t = g.GetCellData().GetArray("template")
    templates |= {int(t.GetValue(i)) for i in range(g.GetNumberOfCells())}
    if len(templates) != b + 1:
        sys.exit(f"block {b} holds templates {sorted(templates)}")
print(n)
PY
)
[ "$read_cells" = "$cells" ] && pass "VTK reads $read_cells cells from the blocks = report" \
  || fail "VTK read '$read_cells' cells, report says $cells"
expect_exit 0 "render 3D .png" -- "$BIN" render "$TMP/tsv.tmesh" --color region -o "$TMP/tsv.png"
png_size "$TMP/tsv.png" > /dev/null && pass "3D PNG signature" || fail "3D PNG"
"$BIN" render "$TMP/tsv.tmesh" -o "$TMP/tsv2.vtm" --quiet
cmp -s "$TMP/tsv/tsv_0.vtu" "$TMP/tsv2/tsv2_0.vtu" && pass ".vtu blocks deterministic" || fail ".vtu blocks differ"

# Bad input: exit 2, one line, no output file.
bad() {
  local what=$1 out=$2; shift 2
  rm -f "$out"
  expect_exit 2 "$what" -- "$BIN" render "$@"
  [ "$(wc -l < "$TMP/stderr")" -eq 1 ] && pass "$what: one-line error" || fail "$what: $(wc -l < "$TMP/stderr") lines"
  if ls "$out"* > /dev/null 2>&1; then fail "$what left $(ls "$out"*)"; else pass "$what: no output file"; fi
}
bad "missing file" "$TMP/m.svg" "$TMP/missing.tmesh" -o "$TMP/m.svg"
bad "unknown --color" "$TMP/c.svg" "$TMP/bridge.tmesh" --color pink -o "$TMP/c.svg"
bad "3D with --color quality" "$TMP/q.png" "$TMP/tsv.tmesh" --color quality -o "$TMP/q.png"
bad "unknown output format" "$TMP/x.pdf" "$TMP/bridge.tmesh" -o "$TMP/x.pdf"
bad "a .json instead of a .tmesh" "$TMP/j.svg" "$TMP/bridge.json" -o "$TMP/j.svg"
bad "--width 5" "$TMP/w.svg" "$TMP/bridge.tmesh" --width 5 -o "$TMP/w.svg"
echo '{"symmesh": "templated-mesh/1", "dimension": 2' > "$TMP/broken.tmesh"
bad "malformed .tmesh" "$TMP/b.svg" "$TMP/broken.tmesh" -o "$TMP/b.svg"

# --patches: the boundary patches of the structure the mesh came from, one path per class.
expect_exit 0 "bridge with --patches" -- "$BIN" render "$TMP/bridge.tmesh" --patches "$TMP/bridge.json" -o "$TMP/bridge.patches.svg" --quiet
classes=$("$BIN" bpp "$TMP/bridge.json" -o "$TMP/bridge.bpp.json" --quiet 2>/dev/null; /usr/bin/python3 -c "
import json,sys; b=json.load(open('$TMP/bridge.bpp.json')); print(len({p['class'] for p in b['patches'] if p['dimension'] == 1}))")
drawn=$(grep -c '<path class="patches"' "$TMP/bridge.patches.svg")
[ "$drawn" = "$classes" ] && pass "one patch path per facet-patch class ($drawn)" \
  || fail "patch paths: $drawn, facet-patch classes in bpp: $classes"
"$BIN" example mosfet -o "$TMP/mosfet.json"
bad "--patches of another structure" "$TMP/p.svg" "$TMP/bridge.tmesh" --patches "$TMP/mosfet.json" -o "$TMP/p.svg"
bad "--patches with .vtm" "$TMP/p.vtm" "$TMP/bridge.tmesh" --patches "$TMP/bridge.json" -o "$TMP/p.vtm"
finish
