#!/usr/bin/env bash
# symmesh solve (spec/fem.md): P1 FEM on templated meshes. The TCSR solver, the CSR solver
# (Algorithm 7.1), PETSc on the TCSR operator (MATSHELL, 1 and 2 MPI ranks) and PETSc on the CSR
# (MATAIJ) give the same solution to 1e-10 relative in the maximum norm, in 2D and 3D; the
# solution is point data "u" of a .vtu that meshio reads; bad input exits 2 naming the field and
# writes nothing.
source "$(dirname "$0")/common.sh" "$@"
PY=/usr/bin/python3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1

"$BIN" example ngon-slice-8 -o "$TMP/ns8.json"
"$BIN" generate "$TMP/ns8.json" --size 0.04 --templated "$TMP/ns8.tmesh" --quiet \
  || fail "generate the 8-gon"
"$BIN" example tsv-8 -o "$TMP/tsv8.json"
"$BIN" generate "$TMP/tsv8.json" --size 0.3 --templated "$TMP/tsv8.tmesh" --quiet \
  || fail "generate the 8-TSV"
cat > "$TMP/bc2.json" <<'EOF'
{"symmesh": "boundary-conditions/1", "source": 1,
 "dirichlet": [{"on": {"box": {"min": [-2, -2], "max": [0, 2]}}, "value": 0}],
 "neumann": [{"on": {"box": {"min": [0.5, -2], "max": [2, 2]}}, "flux": 0.25}]}
EOF
cat > "$TMP/bc3.json" <<'EOF'
{"symmesh": "boundary-conditions/1",
 "dirichlet": [{"on": {"box": {"min": [-100, -100, -100], "max": [100, 100, 0]}}, "value": 0},
               {"on": {"region": 2}, "value": 1}]}
EOF

# solve NAME MESH BC SOLVER [RANKS] [extra...]
solve() {
  local name=$1 mesh=$2 bc=$3 solver=$4 ranks=${5:-1}
  shift 5 2> /dev/null || shift $#
  local run=("$BIN")
  [ "$ranks" -gt 1 ] && run=(mpirun -n "$ranks" "$BIN")
  if "${run[@]}" solve "$mesh" --bc "$bc" --solver "$solver" -o "$TMP/$name.vtu" \
      --report "$TMP/$name.json" "$@" 2> "$TMP/err"; then
    grep -q "symmesh solve: .* unknowns, .* CG iterations" "$TMP/err" \
      || fail "$name: no summary line on stderr"
    pass "$name solved ($solver, $ranks rank(s))"
  else
    fail "$name: solve failed"; sed 's/^/  | /' "$TMP/err"
  fi
}

# same REFERENCE OTHER...: maximum-norm difference relative to max |u| <= 1e-10
same() {
  local ref=$1; shift
  if msg=$($PY - "$TMP/$ref.vtu" "${@/#/$TMP/}" <<'EOF'
import sys, meshio, numpy as np
ref = meshio.read(sys.argv[1]).point_data["u"]
assert np.isfinite(ref).all() and np.abs(ref).max() > 0
for path in sys.argv[2:]:
    u = meshio.read(path + ".vtu").point_data["u"]
    d = np.abs(u - ref).max() / np.abs(ref).max()
    assert d <= 1e-10, (path, d)
    print(path.split("/")[-1], "%.1e" % d)
EOF
  ); then pass "$ref agrees with: $(echo $msg)"; else fail "$ref: $msg"; fi
}

solve ng_tcsr "$TMP/ns8.tmesh" "$TMP/bc2.json" tcsr 1 --coefficient 1=3 --templated "$TMP/u.tmesh"
# The solution per template: every instance's values over its template's vertices, the same
# numbers as the .vtu's point data.
$PY - "$TMP/u.tmesh" "$TMP/ng_tcsr.vtu" <<'EOF' && pass "--templated writes u per instance" || fail "--templated output"
import json, sys, meshio, numpy as np
t = json.load(open(sys.argv[1]))
u = meshio.read(sys.argv[2]).point_data["u"]
values = []
for tp in t["templates"]:
    for inst in tp["instances"]:
        assert len(inst["point_data"]["u"]) == len(tp["vertices"])
        values += inst["point_data"]["u"]
assert set(np.round(values, 15)) == set(np.round(u, 15)), "values differ"
EOF
solve ng_csr "$TMP/ns8.tmesh" "$TMP/bc2.json" csr 1 --coefficient 1=3
solve ng_petsc "$TMP/ns8.tmesh" "$TMP/bc2.json" petsc 1 --coefficient 1=3
solve ng_aij "$TMP/ns8.tmesh" "$TMP/bc2.json" petsc-aij 1 --coefficient 1=3
solve ng_mpi "$TMP/ns8.tmesh" "$TMP/bc2.json" petsc 2 --coefficient 1=3
same ng_tcsr ng_csr ng_petsc ng_aij ng_mpi
$PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['ranks'] == 2 and r['iterations'] > 0, r" \
  "$TMP/ng_mpi.json" && pass "the 2-rank report says 2 ranks" || fail "2-rank report"
# A reaction term (the templates' mass matrices): TCSR, CSR and PETSc on 2 ranks agree.
solve rx_tcsr "$TMP/ns8.tmesh" "$TMP/bc2.json" tcsr 1 --reaction 1=2
solve rx_csr "$TMP/ns8.tmesh" "$TMP/bc2.json" csr 1 --reaction 1=2
solve rx_mpi "$TMP/ns8.tmesh" "$TMP/bc2.json" petsc 2 --reaction 1=2
same rx_tcsr rx_csr rx_mpi
solve tsv_tcsr "$TMP/tsv8.tmesh" "$TMP/bc3.json" tcsr 1 --coefficient 1=2
solve tsv_petsc "$TMP/tsv8.tmesh" "$TMP/bc3.json" petsc 1 --coefficient 1=2
solve tsv_mpi "$TMP/tsv8.tmesh" "$TMP/bc3.json" petsc 2 --coefficient 1=2
same tsv_tcsr tsv_petsc tsv_mpi
# The maximum principle: u between its Dirichlet values 0 and 1 (no source).
$PY -c "import json,sys; r=json.load(open(sys.argv[1])); assert -1e-9 <= r['u_min'] and r['u_max'] <= 1 + 1e-9, r" \
  "$TMP/tsv_tcsr.json" && pass "3D solution within its boundary values" || fail "3D bounds"

# Bad input: exit 2, one line naming the field, no output file.
bad() {
  local what=$1 pattern=$2; shift 2
  expect_exit 2 "$what" -- "$BIN" solve "$@" -o "$TMP/bad.vtu"
  grep -q -- "$pattern" "$TMP/stderr" || { fail "$what: message lacks '$pattern'"; sed 's/^/  | /' "$TMP/stderr"; }
  [ "$(wc -l < "$TMP/stderr")" -eq 1 ] || fail "$what: not one line"
  [ ! -e "$TMP/bad.vtu" ] || fail "$what: left an output file"
}
echo '{"symmesh": "boundary-conditions/1", "dirichlet": [{"on": {"regoin": 1}, "value": 0}]}' > "$TMP/b1.json"
bad "unknown selector key" "dirichlet\[0\].on.regoin: unknown key" "$TMP/ns8.tmesh" --bc "$TMP/b1.json"
echo '{"symmesh": "boundary-conditions/1", "dirichlet": [{"on": {"region": 9}, "value": 0}]}' > "$TMP/b2.json"
bad "a selector that selects nothing" "dirichlet\[0\].on: selects no boundary facet" "$TMP/ns8.tmesh" --bc "$TMP/b2.json"
echo '{"symmesh": "boundary-conditions/1", "neumann": [{"on": {}, "flux": 1}]}' > "$TMP/b3.json"
bad "no Dirichlet data (singular)" "no Dirichlet data" "$TMP/ns8.tmesh" --bc "$TMP/b3.json"
echo '{"symmesh": "boundary-conditions/1", "dirichlet": [{"on": {}, "value": NaN}]}' > "$TMP/b4.json"
bad "malformed JSON" "malformed JSON" "$TMP/ns8.tmesh" --bc "$TMP/b4.json"
bad "a coefficient of a region no instance has" "no instance has region 7" "$TMP/ns8.tmesh" --bc "$TMP/bc2.json" --coefficient 7=1
bad "a non-positive coefficient" "must be a positive" "$TMP/ns8.tmesh" --bc "$TMP/bc2.json" --coefficient 1=-2
bad "a negative reaction" "--reaction 1=-1: must be a finite number >= 0" "$TMP/ns8.tmesh" --bc "$TMP/bc2.json" --reaction 1=-1
bad "an unknown solver" "--solver magic" "$TMP/ns8.tmesh" --bc "$TMP/bc2.json" --solver magic
bad "a missing mesh" "cannot open" "$TMP/none.tmesh" --bc "$TMP/bc2.json"
expect_exit 2 "a solution file that is not .vtu" -- "$BIN" solve "$TMP/ns8.tmesh" --bc "$TMP/bc2.json" -o "$TMP/u.msh"
[ ! -e "$TMP/u.msh" ] || fail "a refused output format left a file"
expect_exit 1 "CG that cannot converge in 2 iterations exits 1 and writes nothing" -- \
  "$BIN" solve "$TMP/ns8.tmesh" --bc "$TMP/bc2.json" --max-iterations 2 -o "$TMP/slow.vtu"
[ ! -e "$TMP/slow.vtu" ] || fail "a non-converged solve left a file"
# The Gummel star (Section 7.5) at about 1.2e2 triangles: symmetric meshes give solutions whose
# rotated / mirrored differences are <= 1e-12, non-symmetric ones >= 1e-4 (bench/gummel.py).
if $PY bench/gummel.py "$BIN" "$TMP" --smoke 2> "$TMP/gummel.err"; then
  pass "Gummel star: symmetric meshes give symmetric solutions ($(tr '\n' ';' < "$TMP/gummel.err" | tr -s ' '))"
else
  fail "Gummel star targets"; sed 's/^/  | /' "$TMP/gummel.err"
fi
"$BIN" solve --help | grep -q "MATSHELL" && pass "solve --help describes the solvers" || fail "solve --help"
finish
