#!/usr/bin/env bash
# symmesh check: verdicts, exit codes, --json keys, bad input (one line, exit 2, no output file).
source "$(dirname "$0")/common.sh" "$@"

expect_exit 0 "Fig 4.3 is a templated mesh" -- "$BIN" check data/fig_4_3_templated_mesh.json
expect_exit 1 "Fig 4.4 is a templated structure but not a templated mesh" -- "$BIN" check data/fig_4_4_nonconforming.json
if grep -q "Lemma 4.2" "$TMP/stdout" "$TMP/stderr" && grep -qE "failing pair T_\{[0-9]+,[0-9]+\}, T_\{[0-9]+,[0-9]+\}" "$TMP/stdout"; then
  pass "Fig 4.4 report names Lemma 4.2 and the failing pair"
else fail "Fig 4.4 report does not name Lemma 4.2 and the failing pair"; fi
expect_exit 0 "Fig 4.5 reflection" -- "$BIN" check data/fig_4_5_reflection.json
expect_exit 0 "3D reflected cube" -- "$BIN" check data/reflected_cube_3d.json
expect_exit 0 "2D geometry template" -- "$BIN" check data/square_geometry_2d.json

# --json has the documented keys and agrees with the exit code.
"$BIN" check --json data/fig_4_4_nonconforming.json > "$TMP/r.json" 2>/dev/null
if /usr/bin/python3 - "$TMP/r.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
for k in ["templated_structure", "templated_mesh", "dimension", "templates", "instances",
          "instance_graph_edges", "lemma_4_2"]:
    assert k in r, k
assert r["templated_structure"] is True and r["templated_mesh"] is False
assert r["lemma_4_2"]["holds"] is False and len(r["lemma_4_2"]["failing_pair"]) == 2
assert r["lemma_4_2"]["condition"] in ("(i)", "(ii)")
assert r["lemma_4_2"]["agrees_with_direct_check"] is True
PY
then pass "--json keys and Lemma 4.2 detail"; else fail "--json keys"; fi

# Determinism: same input, byte-identical output.
"$BIN" check --json data/fig_4_6_instance_graph.json > "$TMP/a.json" 2>/dev/null
"$BIN" check --json data/fig_4_6_instance_graph.json > "$TMP/b.json" 2>/dev/null
if cmp -s "$TMP/a.json" "$TMP/b.json"; then pass "deterministic --json"; else fail "--json differs between runs"; fi

# Bad input: exit 2, exactly one line on stderr naming the problem, nothing written.
check_bad() {
  local file=$1 pattern=$2
  expect_exit 2 "bad input $(basename "$file")" -- "$BIN" graph "$file" -o "$TMP/should_not_exist.svg"
  local lines
  lines=$(wc -l < "$TMP/stderr")
  if [ "$lines" -eq 1 ] && grep -qiE "$pattern" "$TMP/stderr"; then pass "one-line message for $(basename "$file"): $(cat "$TMP/stderr")"
  else fail "message for $file (want one line matching '$pattern'):"; sed 's/^/  | /' "$TMP/stderr"; fi
  if [ -e "$TMP/should_not_exist.svg" ] || [ -e "$TMP/should_not_exist.svg.tmp" ]; then fail "output written for $file"; rm -f "$TMP"/should_not_exist*; else pass "no output file for $(basename "$file")"; fi
  expect_exit 2 "check rejects $(basename "$file")" -- "$BIN" check "$file"
}
check_bad tests/data/bad/malformed.json "malformed|parse|syntax"
check_bad tests/data/bad/nonorthogonal_matrix.json "orthogonal"
check_bad tests/data/bad/overlapping_instances.json "overlap|4\.2"
check_bad tests/data/bad/nan.json "nan|number"
check_bad tests/data/bad/missing_field.json "missing"
check_bad tests/data/bad/unknown_transformation.json "transformation"
expect_exit 2 "missing file" -- "$BIN" check "$TMP/nope.json"
expect_exit 2 "unknown option" -- "$BIN" check --frobnicate data/fig_4_3_templated_mesh.json
if [ "$(wc -l < "$TMP/stderr")" -eq 1 ]; then pass "unknown option: one line"; else fail "unknown option message is not one line"; fi
expect_exit 2 "unknown graph format" -- "$BIN" graph data/fig_4_3_templated_mesh.json -o "$TMP/g.pdf"
[ -e "$TMP/g.pdf" ] && fail "pdf written" || pass "no file for unknown format"
finish
