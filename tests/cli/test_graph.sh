#!/usr/bin/env bash
# symmesh graph: SVG edge count equals the instance graph's (self-loops included), DOT and PNG.
source "$(dirname "$0")/common.sh" "$@"

for f in data/fig_4_6_instance_graph.json data/fig_4_3_templated_mesh.json data/fig_4_5_reflection.json; do
  expect_exit 0 "graph svg $(basename "$f")" -- "$BIN" graph "$f" -o "$TMP/g.svg"
  svg_edges=$(grep -c 'class="edge"' "$TMP/g.svg")
  json_edges=$("$BIN" check --json "$f" 2>/dev/null | /usr/bin/python3 -c 'import json,sys; print(json.load(sys.stdin)["instance_graph_edges"])')
  if [ "$svg_edges" -eq "$json_edges" ] && [ "$svg_edges" -gt 0 ]; then pass "$(basename "$f"): SVG has $svg_edges edges = check --json"
  else fail "$(basename "$f"): SVG has $svg_edges edges, check --json says $json_edges"; fi
  loops=$("$BIN" check --json "$f" 2>/dev/null | /usr/bin/python3 -c 'import json,sys; r=json.load(sys.stdin); print(sum(1 for e in r["instance_graph"]["edges"] if e["templates"][0]==e["templates"][1]))')
  [ "$loops" -ge "$("$BIN" check --json "$f" 2>/dev/null | /usr/bin/python3 -c 'import json,sys; print(json.load(sys.stdin)["templates"])')" ] && pass "every template has a self-loop" || fail "missing self-loops"
done

expect_exit 0 "graph dot" -- "$BIN" graph data/fig_4_6_instance_graph.json -o "$TMP/g.dot"
dot_edges=$(grep -c -- ' -- ' "$TMP/g.dot")
json_edges=$("$BIN" check --json data/fig_4_6_instance_graph.json 2>/dev/null | /usr/bin/python3 -c 'import json,sys; print(json.load(sys.stdin)["instance_graph_edges"])')
[ "$dot_edges" -eq "$json_edges" ] && pass "DOT has $dot_edges edges" || fail "DOT has $dot_edges edges, want $json_edges"
# The DOT is valid Graphviz input with the same number of edges.
if dot -Tsvg "$TMP/g.dot" -o "$TMP/from_dot.svg" && [ "$(grep -c 'class="edge"' "$TMP/from_dot.svg")" -eq "$json_edges" ]; then
  pass "dot(1) renders the DOT with all edges"; else fail "dot(1) on the DOT output"; fi

expect_exit 0 "graph png" -- "$BIN" graph data/fig_4_6_instance_graph.json -o "$TMP/g.png"
if head -c 8 "$TMP/g.png" | od -An -c | grep -q 'P   N   G'; then pass "PNG signature"; else fail "not a PNG"; fi
finish
