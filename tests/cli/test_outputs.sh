#!/usr/bin/env bash
# Output files of `symmesh generate` (spec/outputs.md#mesh-files, #orientation, #progress) and the
# refusals before any work (spec/generation.md#cell-estimate): binary, compressed and ASCII .vtu
# read by VTK (ParaView's reader, python3-vtk9) and meshio with the cell data intact, binary and
# ASCII .msh read by gmsh and meshio, positive cells, byte-identical reruns, an infeasible --size
# refused in under a second with the estimate, --min-angle checked before the partition.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3

"$BIN" example mosfet -o "$TMP/mosfet.json"
AREA=$($PY tests/cli/geometry_area.py "$TMP/mosfet.json")
gen() { "$BIN" generate "$TMP/mosfet.json" --size 0.1 --quiet "$@"; }

# The reflective MOSFET in every encoding: meshio checks (conforming, all counter-clockwise, area).
for variant in "m.vtu" "mz.vtu --compress" "ma.vtu --ascii" "m.msh" "ma.msh --ascii" "m.mesh"; do
  set -- $variant
  if ! gen -o "$TMP/$1" --report "$TMP/$1.json" ${2:-} 2> "$TMP/err"; then
    fail "$variant: generate failed"; sed 's/^/  | /' "$TMP/err"; continue; fi
  if msg=$($PY tests/cli/structure_instance_checks.py "$TMP/$1" "$TMP/$1.json" "$AREA" 2>&1); then
    pass "$variant: $(echo "$msg" | tail -1)"; else fail "$variant: $msg"; fi
done
head -c 400 "$TMP/m.vtu" | grep -q 'format="appended"' && pass ".vtu is binary (appended) by default" \
  || fail ".vtu default is not appended binary"
grep -q 'compressor="vtkZLibDataCompressor"' "$TMP/mz.vtu" && pass "--compress uses VTK's zlib compressor" \
  || fail "--compress: no compressor attribute"
[ "$(stat -c %s "$TMP/mz.vtu")" -lt "$(stat -c %s "$TMP/m.vtu")" ] && pass "compressed .vtu is smaller" \
  || fail "compressed .vtu is not smaller"
sed -n 2p "$TMP/m.msh" | grep -q "^4.1 1 8" && pass ".msh is MSH 4.1 binary by default" || fail ".msh header: $(sed -n 2p "$TMP/m.msh")"
sed -n 2p "$TMP/ma.msh" | grep -q "^4.1 0 8" && pass "--ascii .msh is MSH 4.1 text" || fail "ascii .msh header"

# VTK's XML reader (what ParaView uses) and meshio read the three .vtu encodings to the same
# points, cells and cell data.
if msg=$($PY - "$TMP/m.vtu" "$TMP/mz.vtu" "$TMP/ma.vtu" "$TMP/m.vtu.json" <<'PYEOF' 2>&1
import json, sys
import meshio, numpy as np
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
from vtkmodules.util.numpy_support import vtk_to_numpy
report = json.load(open(sys.argv[4]))
ref = None
for path in sys.argv[1:4]:
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    assert r.GetErrorCode() == 0, (path, r.GetErrorCode())
    g = r.GetOutput()
    assert g.GetNumberOfCells() == report["cells_structure_instance"], path
    assert g.GetNumberOfPoints() == report["vertices_structure_instance"], path
    data = {name: vtk_to_numpy(g.GetCellData().GetArray(name)) for name in ("region", "template", "instance")}
    pts = vtk_to_numpy(g.GetPoints().GetData())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    m = meshio.read(path)
    assert np.array_equal(m.points, pts), path
    assert np.array_equal(m.cells_dict["triangle"].ravel(), conn), path
    for name, v in data.items():
        assert np.array_equal(np.concatenate(m.cell_data[name]), v), (path, name)
    cur = (pts, conn, data)
    if ref is None:
        ref = cur
    else:
        assert np.array_equal(ref[0], cur[0]) and np.array_equal(ref[1], cur[1]), path
        for name in ref[2]:
            assert np.array_equal(ref[2][name], cur[2][name]), (path, name)
assert set(np.unique(ref[2]["instance"])) == set(range(1, report["instances"] + 1))
print(f"{len(conn) // 3} cells, regions {sorted(set(ref[2]['region'].tolist()))}, "
      f"{report['instances']} instances: VTK and meshio agree on all three encodings")
PYEOF
); then pass "$msg"; else fail "VTK/meshio round trip: $msg"; fi

for f in m.msh ma.msh; do
  cells=$($PY -c "import json,sys; print(json.load(open(sys.argv[1]))['cells_structure_instance'])" "$TMP/$f.json")
  if gmsh -check "$TMP/$f" > "$TMP/gmsh.out" 2>&1 && grep -q "Info *: $cells elements" "$TMP/gmsh.out" && \
     ! grep -qiE "error|duplicate (nodes|elements) found" "$TMP/gmsh.out"; then
    pass "gmsh opens $f: $cells elements"; else fail "gmsh on $f"; tail -3 "$TMP/gmsh.out"; fi
done

# Same input, same bytes, in every encoding.
for variant in "m.vtu" "mz.vtu --compress" "m.msh" "ma.msh --ascii"; do
  set -- $variant
  gen -o "$TMP/again_$1" ${2:-}
  cmp -s "$TMP/$1" "$TMP/again_$1" && pass "$1: byte-identical rerun" || fail "$1: rerun differs"
done

# An infeasible size is refused at once with the estimate and the limit; nothing is written.
start=$(date +%s.%N)
expect_exit 2 "--size 1e-9" -- "$BIN" generate "$TMP/mosfet.json" --size 1e-9 -o "$TMP/huge.vtu"
took=$($PY -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(date +%s.%N)")
$PY -c "import sys; sys.exit(0 if float(sys.argv[1]) < 1.0 else 1)" "$took" \
  && pass "refused in ${took:0:5} s" || fail "refusal took $took s"
grep -q "about 6.62e+19 triangles (area 13.2.*above the limit of" "$TMP/stderr" && [ "$(wc -l < "$TMP/stderr")" -eq 1 ] \
  && pass "one line with the estimate and the limit" || fail "message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/huge.vtu" ] && [ ! -e "$TMP/huge.vtu.part" ] && pass "no file for an infeasible size" || fail "file written"
expect_exit 2 "--max-cells below the estimate" -- "$BIN" generate "$TMP/mosfet.json" --size 0.1 --max-cells 1000 -o "$TMP/few.vtu"
grep -q "above the limit of 1e+03 (--max-cells)" "$TMP/stderr" && pass "message names --max-cells" || fail "message: $(cat "$TMP/stderr")"
gen --max-cells 20000 -o "$TMP/enough.vtu" && pass "--max-cells above the estimate generates" || fail "--max-cells 20000"

# Options are checked before any work: --min-angle names itself, no stage ran.
expect_exit 2 "--min-angle 40" -- "$BIN" generate "$TMP/mosfet.json" --size 0.1 --min-angle 40 -o "$TMP/a.vtu"
grep -q "^symmesh: error: --min-angle 40: must be between 0 and 33.8" "$TMP/stderr" && [ "$(wc -l < "$TMP/stderr")" -eq 1 ] \
  && pass "the error names --min-angle and nothing ran before it" || fail "message: $(cat "$TMP/stderr")"
expect_exit 2 "--compress with .msh" -- "$BIN" generate "$TMP/mosfet.json" --size 0.1 --compress -o "$TMP/c.msh"
expect_exit 2 "--size nan" -- "$BIN" generate "$TMP/mosfet.json" --size nan -o "$TMP/n.vtu"
[ ! -e "$TMP/a.vtu" ] && [ ! -e "$TMP/c.msh" ] && [ ! -e "$TMP/n.vtu" ] && pass "no file for a bad option" || fail "file written for a bad option"

# -o, --templated and --report appear together or not at all (spec/outputs.md#atomic-files).
expect_exit 2 "--report in a missing directory" -- "$BIN" generate "$TMP/mosfet.json" --size 0.5 \
  -o "$TMP/group.vtu" --templated "$TMP/group.tmesh" --report "$TMP/no-such-dir/r.json" --quiet
[ -z "$(ls "$TMP" | grep '^group\.')" ] && pass "no -o, --templated or .part file when --report fails" \
  || fail "left behind: $(ls "$TMP" | grep '^group\.')"

# A stage longer than 2 s shows progress lines with counts at least every 2 s (conventional
# meshing of the 128-gon at ~8e5 triangles takes several seconds on the CI machine).
"$BIN" example ngon-slice-128 -o "$TMP/n128.json"
"$BIN" generate "$TMP/n128.json" --size 0.0045 --method conventional -o "$TMP/n128.vtu" 2> "$TMP/progress"
if $PY - "$TMP/progress" <<'PYEOF'
import re, sys
times = [float(t) for t in re.findall(r"\[(\d+\.\d+) s\]", open(sys.argv[1]).read())]
counted = re.findall(r"template meshing: \d+/\d+ triangles", open(sys.argv[1]).read())
gaps = [b - a for a, b in zip(times, times[1:])]
assert times and max(gaps) <= 2.1, (times, gaps)
assert times[-1] < 2.2 or counted, "no counted progress line during meshing"
print(f"{len(times)} lines over {times[-1]:.1f} s, largest gap {max(gaps):.2f} s")
PYEOF
then pass "progress lines at least every 2 s"; else fail "progress: $(tail -5 "$TMP/progress")"; fi
finish
