#!/usr/bin/env bash
# Every command of docs/tutorial.md, in its order, writing into OUT (default out/tutorial):
# check, instance graph, boundary patches, generation (ParaView .vtu, Gmsh .msh, templated
# .tmesh), pictures of the mesh, a solve and its picture, and the 3D open TSV. `make demo` runs it;
# the pictures in docs/tutorial/ are its output (`bash scripts/tutorial.sh build/symmesh
# docs/tutorial --pictures`), and tests/cli/test_tutorial.sh checks that they are reproduced
# byte for byte. Usage: tutorial.sh [BIN] [OUT] [--pictures]
set -euo pipefail
bin=${1:-build/symmesh}
out=${2:-out/tutorial}
pictures_only=${3:-}
here=$(cd "$(dirname "$0")/.." && pwd)
ex="$here/examples/tutorial"
work=$out
if [ "$pictures_only" = "--pictures" ]; then work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; fi
mkdir -p "$out" "$work"
run() { echo "+ $*" >&2; "$@"; }

# 1. The hand-written geometry: is it a templated structure, and a templated geometry?
run "$bin" check "$ex/plate.json" | sed "s|$ex/||" > "$out/plate.check.txt"
# 2. Its instance graph (template view, and one node per instance) and boundary patches.
run "$bin" graph "$ex/plate.json" -o "$out/plate.graph.svg"
run "$bin" graph "$ex/plate.json" --view instances -o "$out/plate.instances.svg"
run "$bin" bpp "$ex/plate.json" -o "$out/plate.bpp.svg"
# 3. A templated mesh: the structure instance for ParaView (.vtu) and Gmsh (.msh), the templates
#    with their transformations (.tmesh) and a report.
run "$bin" generate "$ex/plate.json" --size 0.2 --min-angle 25 -o "$work/plate.vtu" \
  --templated "$work/plate.tmesh" --report "$work/plate.report.json" --quiet
run "$bin" generate "$ex/plate.json" --size 0.2 --min-angle 25 -o "$work/plate.msh" --quiet
# 4. Pictures of it: cells by instance, by smallest angle, and the boundary patches over them.
run "$bin" render "$work/plate.tmesh" --color instance -o "$out/plate.instance.svg" --quiet
run "$bin" render "$work/plate.tmesh" --color quality -o "$out/plate.quality.svg" --quiet
run "$bin" render "$work/plate.tmesh" --patches "$ex/plate.json" -o "$out/plate.patches.svg" --quiet
# 5. A solve on the templated mesh (P1 FEM, TCSR + CG), and its picture.
run "$bin" solve "$work/plate.tmesh" --bc "$ex/plate.bc.json" --coefficient 2=10 \
  -o "$work/plate.u.vtu" --report "$work/plate.u.report.json" --quiet
run /usr/bin/python3 "$here/scripts/plot_solution.py" "$work/plate.u.vtu" \
  --title "u with κ = 10 in the bushings" -o "$out/plate.u.svg"
# 6. 3D: the built-in open TSV with 8 vias, by rotational slices; a ParaView multiblock (one
#    block per template) and a picture of its boundary surface.
run "$bin" example tsv-8 -o "$work/tsv-8.json"
run "$bin" generate "$work/tsv-8.json" --size 0.3 -o "$work/tsv-8.vtu" \
  --templated "$work/tsv-8.tmesh" --report "$work/tsv-8.report.json" --quiet
run "$bin" render "$work/tsv-8.tmesh" -o "$work/tsv-8.vtm" --quiet
run "$bin" render "$work/tsv-8.tmesh" --color region -o "$out/tsv-8.surface.svg" --quiet
echo "tutorial: outputs in $out/" >&2
