#!/usr/bin/env bash
# The main job on built-in examples: check the Fig. 4.3 templated mesh and the Fig. 4.4
# non-conforming structure, render instance graphs and boundary patch partitions (Figs 4.10,
# 6.8, a 3D rotational slice), spot-check the interface lemmas, generate templated meshes of
# built-in 2D objects and the 3D open TSV, and draw them (symmesh render: every built-in 2D
# object into out/render/).
set -uo pipefail
bin=${1:-build/symmesh}
out=${2:-out}
mkdir -p "$out"
run() { echo "+ $*" >&2; "$@"; }

run "$bin" check data/fig_4_3_templated_mesh.json | tee "$out/fig_4_3_check.txt"
run "$bin" check --json data/fig_4_3_templated_mesh.json > "$out/fig_4_3_check.json"
run "$bin" check --json data/fig_4_4_nonconforming.json > "$out/fig_4_4_check.json"
rc=$?
[ "$rc" -eq 1 ] || { echo "demo: expected exit 1 for Fig. 4.4, got $rc" >&2; exit 1; }
run "$bin" check data/fig_4_4_nonconforming.json > "$out/fig_4_4_check.txt" 2>&1
run "$bin" graph data/fig_4_3_templated_mesh.json -o "$out/fig_4_3_instance_graph.svg" || exit 1
run "$bin" graph data/fig_4_6_instance_graph.json -o "$out/fig_4_6_instance_graph.svg" || exit 1
run "$bin" graph data/fig_4_6_instance_graph.json -o "$out/fig_4_6_instance_graph.dot" || exit 1
run "$bin" check --json data/reflected_cube_3d.json > "$out/reflected_cube_3d_check.json" || exit 1
run "$bin" bpp data/fig_4_10_partition.json -o "$out/fig_4_10_bpp.svg" || exit 1
run "$bin" bpp data/fig_6_8_multiregion_rotational.json -o "$out/fig_6_8_bpp.svg" || exit 1
run "$bin" bpp data/fig_6_8_multiregion_rotational.json -o "$out/fig_6_8_bpp.json" || exit 1
run "$bin" bpp data/rotational_slice_3d.json -o "$out/rotational_slice_3d_bpp.vtu" || exit 1
# Templated mesh generation (Algorithm 5.6) on built-in 2D objects: structure instance (.vtu,
# .msh), templated mesh (.tmesh), report with byte counts, timings and quality.
for name in ngon-sao-16 bridge mosfet star-reflective-rotational; do
  run "$bin" example "$name" -o "$out/$name.json" || exit 1
  run "$bin" generate "$out/$name.json" --size 0.05 --min-angle 25 -o "$out/$name.vtu" \
    --templated "$out/$name.tmesh" --report "$out/$name.report.json" || exit 1
done
run "$bin" generate "$out/ngon-sao-16.json" --size 0.05 --min-angle 25 -o "$out/ngon-sao-16.msh" --quiet || exit 1
# The 64-gon by rotational slices (Section 6.3) next to the same mesher and Gmsh on the whole.
run "$bin" example ngon-slice-64 -o "$out/ngon-slice-64.json" || exit 1
for method in rotational conventional gmsh; do
  run "$bin" generate "$out/ngon-slice-64.json" --size 0.02 --min-angle 25 --method "$method" \
    -o "$out/ngon-slice-64.$method.vtu" --report "$out/ngon-slice-64.$method.report.json" --quiet || exit 1
done
# A whole gear cut into its slice (Algorithm 6.2, first ray by Algorithm 6.3), then meshed by the
# rotational method (auto picks it).
run "$bin" example gear -o "$out/gear.json" || exit 1
run "$bin" cut "$out/gear.json" --rotation 12 -o "$out/gear.slice.json" --report "$out/gear.cut.json" || exit 1
run "$bin" generate "$out/gear.slice.json" --size 0.02 --min-angle 25 -o "$out/gear.vtu" \
  --report "$out/gear.report.json" --quiet || exit 1
# 3D (Algorithm 5.7 with TetGen): the 16-TSV by rotational slices (auto picks it) next to TetGen
# on the whole geometry (conventional).
run "$bin" example tsv-16 -o "$out/tsv-16.json" || exit 1
for method in auto conventional; do
  run "$bin" generate "$out/tsv-16.json" --size 0.08 --method "$method" -o "$out/tsv-16.$method.vtu" \
    --templated "$out/tsv-16.$method.tmesh" --report "$out/tsv-16.$method.report.json" --quiet || exit 1
done
# Pictures (spec/outputs.md#render, #instance-graph): every built-in 2D object meshed coarsely
# and rendered (cells by template, red instance interfaces, black boundary), the bridge also by
# smallest angle and by instance; the bridge's instance graph in both views; the 16-TSV as a
# ParaView multiblock (one block per template) and as a boundary-surface picture.
mkdir -p "$out/render"
for name in $("$bin" example --list | cut -f1); do
  json="$out/render/$name.json"
  "$bin" example "$name" -o "$json" || exit 1
  if grep -q '"dimension": 3' "$json"; then rm -f "$json"; continue; fi
  run "$bin" generate "$json" --size 0.1 --templated "$out/render/$name.tmesh" --quiet || exit 1
  run "$bin" render "$out/render/$name.tmesh" -o "$out/render/$name.png" --quiet || exit 1
done
for colour in quality instance; do
  run "$bin" render "$out/bridge.tmesh" --color "$colour" -o "$out/bridge.$colour.png" || exit 1
done
run "$bin" render "$out/bridge.tmesh" --color quality -o "$out/bridge.quality.svg" || exit 1
run "$bin" graph "$out/bridge.json" -o "$out/bridge_instance_graph.png" || exit 1
run "$bin" graph "$out/bridge.json" -o "$out/bridge_instance_graph.dot" || exit 1
run "$bin" graph "$out/bridge.json" --view instances -o "$out/bridge_instances.png" || exit 1
run "$bin" render "$out/tsv-16.auto.tmesh" -o "$out/tsv-16.vtm" || exit 1
run "$bin" render "$out/tsv-16.auto.tmesh" --color region -o "$out/tsv-16.surface.png" || exit 1
# FEM on the templated TSV (spec/fem.md): P1 stiffness per template (TCSR), u = 0 on the bottom
# face, u = 1 on the via's metal (region 2), the solution as point data of the structure instance
# and per template.
cat > "$out/tsv-16.bc.json" <<'JSON'
{"symmesh": "boundary-conditions/1",
 "dirichlet": [{"on": {"box": {"min": [-100, -100, -100], "max": [100, 100, 0]}}, "value": 0},
               {"on": {"region": 2}, "value": 1}]}
JSON
run "$bin" solve "$out/tsv-16.auto.tmesh" --bc "$out/tsv-16.bc.json" --coefficient 1=2 \
  -o "$out/tsv-16.solution.vtu" --templated "$out/tsv-16.solution.tmesh" \
  --report "$out/tsv-16.solution.report.json" --quiet || exit 1
# The tutorial (docs/tutorial.md): a hand-written plate from check to solve, and the 8-TSV.
run bash "$(dirname "$0")/tutorial.sh" "$bin" "$out/tutorial" || exit 1
run "$bin" lemmas --cases 50 --only Lemma_4_2 --out "$out/counterexamples" | tee "$out/lemmas_4_2.txt"
echo
echo "demo: outputs in $out/:"
ls -1 "$out"
