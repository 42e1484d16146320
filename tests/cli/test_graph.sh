#!/usr/bin/env bash
# symmesh graph: the template view (one edge per template pair, labelled with its multiplicity,
# plus the trivial loops), the instance view (one node per instance, one edge per neighbouring
# pair), DOT and PNG; the bridge stays within 2000 px with readable labels; every built-in
# example draws in both views.
source "$(dirname "$0")/common.sh" "$@"

# expected_pairs FILE: "a b n" per unordered template pair with n > 0 non-trivial edges (1-based).
expected_pairs() {
  "$BIN" check --json "$1" 2>/dev/null | /usr/bin/python3 -c '
import collections, json, sys
r = json.load(sys.stdin)
n = collections.Counter(tuple(sorted(e["templates"])) for e in r["instance_graph"]["edges"] if not e["trivial"])
for (a, b), k in sorted(n.items()):
    print(a, b, k)'
}
# dot_pairs DOT: the same from the template view DOT (edge lines, comments left out).
dot_pairs() {
  /usr/bin/python3 - "$1" <<'PY'
import re, sys
out = []
for line in open(sys.argv[1]):
    m = re.match(r"\s*X(\d+) -- X(\d+) \[label=\"(\d+) pairs?\", multiplicity=(\d+)", line)
    if m:
        a, b, label, mult = map(int, m.groups())
        if label != mult:
            sys.exit(f"label {label} != multiplicity {mult}")
        out.append((min(a, b), max(a, b), mult))
for t in sorted(out):
    print(*t)
PY
}
json_value() { "$BIN" check --json "$1" 2>/dev/null | /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)$2)"; }

for f in data/fig_4_6_instance_graph.json data/fig_4_3_templated_mesh.json data/fig_4_5_reflection.json data/perf_32_templates_200_instances.json; do
  b=$(basename "$f")
  expect_exit 0 "graph dot $b" -- "$BIN" graph "$f" -o "$TMP/g.dot"
  want=$(expected_pairs "$f")
  got=$(dot_pairs "$TMP/g.dot" 2>&1)
  [ -n "$want" ] && [ "$got" = "$want" ] && pass "$b: one DOT edge per template pair with its multiplicity ($(echo "$want" | wc -l) pairs)" \
    || fail "$b: DOT pairs '$got', want '$want'"
  templates=$(json_value "$f" '["templates"]')
  loops=$(grep -c 'label="I", style=dashed' "$TMP/g.dot")
  [ "$loops" -eq "$templates" ] && pass "$b: one trivial loop per template" || fail "$b: $loops loops for $templates templates"
  pairs=$(grep -c '^  // X' "$TMP/g.dot")
  nontrivial=$(( $(json_value "$f" '["instance_graph_edges"]') - templates ))
  [ "$pairs" -eq "$nontrivial" ] && pass "$b: the DOT lists all $pairs instance pairs" || fail "$b: DOT lists $pairs pairs, want $nontrivial"
  expect_exit 0 "graph svg $b" -- "$BIN" graph "$f" -o "$TMP/g.svg"
  svg_edges=$(grep -c 'class="edge"' "$TMP/g.svg")
  [ "$svg_edges" -eq $(( $(echo "$want" | wc -l) + templates )) ] && pass "$b: SVG draws $svg_edges edges (pairs + loops)" \
    || fail "$b: SVG draws $svg_edges edges"
  # The DOT is valid Graphviz input.
  dot -Tsvg "$TMP/g.dot" -o "$TMP/from_dot.svg" && [ "$(grep -c 'class="edge"' "$TMP/from_dot.svg")" -eq "$svg_edges" ] \
    && pass "$b: dot(1) renders the DOT" || fail "$b: dot(1) on the DOT output"
done

# The bridge: 2 templates, 48 instances, 62 neighbouring pairs — drawn within 2000 px with labels
# of at least 10 px, in both views.
"$BIN" example bridge -o "$TMP/bridge.json"
# size_px SVG|PNG: "W H min_label_px" of a Graphviz picture (SVG in points at 96 dpi).
size_px() {
  /usr/bin/python3 - "$1" <<'PY'
import re, struct, sys, xml.etree.ElementTree as ET
path = sys.argv[1]
if path.endswith(".png"):
    b = open(path, "rb").read(24)
    assert b[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    print(*struct.unpack(">II", b[16:24]))
    sys.exit()
root = ET.parse(path).getroot()
px = lambda s: float(s.replace("pt", "")) * 96 / 72
w, h = px(root.get("width")), px(root.get("height"))
vb = [float(x) for x in root.get("viewBox").split()]
scale = w / (vb[2] * 96 / 72)  # the viewBox is in points; shrinking scales it down
g = root.find("{http://www.w3.org/2000/svg}g")
m = re.search(r"scale\(([\d.]+)", g.get("transform", ""))
scale *= float(m.group(1)) if m else 1
fonts = [float(t.get("font-size")) for t in root.iter("{http://www.w3.org/2000/svg}text")]
print(round(w), round(h), round(min(fonts) * 96 / 72 * scale, 1))
PY
}
for view in templates instances; do
  for ext in svg png; do
    expect_exit 0 "bridge --view $view .$ext" -- "$BIN" graph "$TMP/bridge.json" --view "$view" -o "$TMP/bridge.$view.$ext"
    read -r w h label <<< "$(size_px "$TMP/bridge.$view.$ext")"
    [ "$w" -le 2000 ] && [ "$h" -le 2000 ] && pass "bridge $view .$ext: $w x $h px (<= 2000)" \
      || fail "bridge $view .$ext: $w x $h px"
    if [ "$ext" = svg ]; then
      awk -v l="$label" 'BEGIN { exit !(l >= 10) }' && pass "bridge $view: labels $label px (>= 10)" \
        || fail "bridge $view: labels $label px"
    fi
  done
done
nodes=$(grep -c 'class="node"' "$TMP/bridge.instances.svg")
edges=$(grep -c 'class="edge"' "$TMP/bridge.instances.svg")
[ "$nodes" -eq 48 ] && [ "$edges" -eq 62 ] && pass "bridge instance view: 48 instance nodes, 62 edges" \
  || fail "bridge instance view: $nodes nodes, $edges edges (want 48, 62)"
"$BIN" graph "$TMP/bridge.json" -o "$TMP/bridge.dot" -q
grep -q '^  X1 -- X2 \[label="62 pairs", multiplicity=62' "$TMP/bridge.dot" && pass "bridge template DOT: X1 -- X2 labelled 62 pairs" \
  || fail "bridge template DOT has no 'X1 -- X2 62 pairs' edge"
"$BIN" graph "$TMP/bridge.json" --view instances -o "$TMP/again.svg" -q
cmp -s "$TMP/bridge.instances.svg" "$TMP/again.svg" && pass "instance view deterministic" || fail "instance view differs between runs"

# Beyond kMaxInstanceViewInstances (400) the instance view is refused, with no output file.
/usr/bin/python3 -c '
import json, sys
inst = [{"transformation": {"translation": [str(i), "0"]}} for i in range(401)]
json.dump({"symmesh": "templated-structure/1", "dimension": 2, "templates": [{"name": "square",
  "kind": "geometry", "polygon": [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]],
  "instances": inst}]}, open(sys.argv[1], "w"))' "$TMP/row.json"
expect_exit 2 "instance view of 401 instances refused" -- "$BIN" graph "$TMP/row.json" --view instances -o "$TMP/row.svg"
grep -q "at most 400 instances" "$TMP/stderr" && pass "the refusal names the limit" || fail "refusal message: $(cat "$TMP/stderr")"
[ ! -e "$TMP/row.svg" ] && [ ! -e "$TMP/row.svg.part" ] && pass "no output file after the refusal" || fail "output left behind"
expect_exit 0 "template view of 401 instances" -- "$BIN" graph "$TMP/row.json" -o "$TMP/row.svg"
expect_exit 2 "unknown --view" -- "$BIN" graph "$TMP/row.json" --view pairs -o "$TMP/v.svg"

# Every built-in example draws in both views (the 32- to 128-slice TSVs, whole or halved, are left
# out: their exact analysis, not the drawing, takes minutes).
for name in $("$BIN" example --list | cut -f1); do
  case "$name" in tsv-32|tsv-64|tsv-128|tsv-half-32|tsv-half-64|tsv-half-128) continue ;; esac
  "$BIN" example "$name" -o "$TMP/ex.json" 2>/dev/null || { fail "example $name"; continue; }
  ok_views=""
  for view in templates instances; do
    "$BIN" graph "$TMP/ex.json" --view "$view" -o "$TMP/ex.png" -q 2> "$TMP/stderr" && ok_views="$ok_views $view" \
      || sed 's/^/  | /' "$TMP/stderr"
  done
  [ "$ok_views" = " templates instances" ] && pass "$name draws in both views" || fail "$name: only '$ok_views'"
done

expect_exit 0 "graph png" -- "$BIN" graph data/fig_4_6_instance_graph.json -o "$TMP/g.png"
if head -c 8 "$TMP/g.png" | od -An -c | grep -q 'P   N   G'; then pass "PNG signature"; else fail "not a PNG"; fi
finish
