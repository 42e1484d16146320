#!/usr/bin/env python3
"""Write data/perf_32_templates_200_instances.json: a larger 2D templated geometry for
performance tests of the boundary patch partition (and check/graph).

32 geometry templates X1..X32, each the unit square with one extra collinear vertex on its
bottom edge at ((t+1)/33, 0), t = 0..31 (so no two templates are equal as polygons), and 200
instances tiling the 20 x 10 block [0,20]x[0,10] of unit cells without overlaps. Cell n
(column n % 20, row n // 20) holds an instance of template n % 32 under one of the eight
symmetries of the square (signed permutations about the cell centre, i.e. 90-degree rotations
and reflections), chosen deterministically, followed by the translation to the cell.
Every instance touches its edge neighbours along a full edge and its diagonal neighbours in a
corner point. Standard library only; the output is deterministic.

Usage: python3 scripts/make_perf_structure.py [OUTPUT]   (default data/perf_32_templates_200_instances.json)
"""
import json
import os
import sys
from fractions import Fraction

COLS, ROWS = 20, 10
N_TEMPLATES = 32
N_INSTANCES = COLS * ROWS  # 200

# the eight symmetries of the square as (perm, sign): output coordinate i = sign[i] * x[perm[i]]
SYMMETRIES = [
    ([0, 1], [1, 1]),    # identity
    ([1, 0], [-1, 1]),   # rotation by 90 degrees
    ([0, 1], [-1, -1]),  # rotation by 180 degrees
    ([1, 0], [1, -1]),   # rotation by 270 degrees
    ([0, 1], [-1, 1]),   # reflection x -> -x
    ([0, 1], [1, -1]),   # reflection y -> -y
    ([1, 0], [1, 1]),    # reflection in the diagonal y = x
    ([1, 0], [-1, -1]),  # reflection in the anti-diagonal
]


def exact(q):
    q = Fraction(q)
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def template(t):
    x = Fraction(t + 1, N_TEMPLATES + 1)
    return {
        "name": f"X{t + 1}",
        "kind": "geometry",
        "polygon": [["0", "0"], [exact(x), "0"], ["1", "0"], ["1", "1"], ["0", "1"]],
        "instances": [],
    }


def instance(n):
    col, row = n % COLS, n // COLS
    perm, sign = SYMMETRIES[(3 * n + row) % 8]
    # map the unit square onto itself about its centre c = (1/2, 1/2), then translate to the cell:
    # x -> A (x - c) + c + (col, row), A = signed permutation; (A c)_i = sign[i] / 2
    half = Fraction(1, 2)
    offset = [col, row]
    translation = [half - sign[i] * half + offset[i] for i in range(2)]
    return {
        "transformation": {
            "signed_permutation": {"perm": perm, "sign": sign, "translation": [exact(v) for v in translation]}
        },
        "region": 1,
    }


def build():
    templates = [template(t) for t in range(N_TEMPLATES)]
    for n in range(N_INSTANCES):
        templates[n % N_TEMPLATES]["instances"].append(instance(n))
    return {
        "symmesh": "templated-structure/1",
        "description": (
            "Performance fixture written by scripts/make_perf_structure.py: 32 geometry templates "
            "(unit squares, template t with an extra collinear vertex at ((t+1)/33, 0) on its bottom edge) "
            "and 200 instances (translations composed with the 8 symmetries of the square) tiling the "
            "20 x 10 block [0,20]x[0,10] without overlaps. Every pair of instances in edge-adjacent cells "
            "touches along a full edge, every pair in diagonally adjacent cells in one corner point: "
            "20*9 + 19*10 = 370 edge contacts and 2*19*9 = 342 corner contacts, so the instance graph has "
            "32 trivial self-loops + 712 interface edges = 744 edges. Expected: a valid templated geometry "
            "(symmesh check exit 0). Expected boundary patch partition (worked out with an independent "
            "brute-force oracle): every template has 4 facet patches (its four edges; the extra collinear "
            "vertex splits nothing) and 4 point patches (its corners, where diagonal neighbours touch in "
            "a point); all 128 edge patches form one class and all 128 corner points another; the instance "
            "graph is irregular (some composition of template boundary mappings maps an edge onto itself "
            "reversed)."
        ),
        "dimension": 2,
        "templates": templates,
    }


def write(doc, path):
    # one instance / one polygon per line: readable and diff-friendly
    lines = ["{"]
    lines.append(f'  "symmesh": {json.dumps(doc["symmesh"])},')
    lines.append(f'  "description": {json.dumps(doc["description"])},')
    lines.append(f'  "dimension": {doc["dimension"]},')
    lines.append('  "templates": [')
    for ti, t in enumerate(doc["templates"]):
        lines.append("    {")
        lines.append(f'      "name": {json.dumps(t["name"])},')
        lines.append(f'      "kind": {json.dumps(t["kind"])},')
        lines.append(f'      "polygon": {json.dumps(t["polygon"])},')
        lines.append('      "instances": [')
        for gi, ins in enumerate(t["instances"]):
            comma = "," if gi + 1 < len(t["instances"]) else ""
            lines.append(f"        {json.dumps(ins)}{comma}")
        lines.append("      ]")
        lines.append("    }" + ("," if ti + 1 < len(doc["templates"]) else ""))
    lines.append("  ]")
    lines.append("}")
    text = "\n".join(lines) + "\n"
    assert json.loads(text) == doc
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "data", "perf_32_templates_200_instances.json")
    write(build(), out)
    print(f"wrote {os.path.normpath(out)}: {N_TEMPLATES} templates, {N_INSTANCES} instances")


if __name__ == "__main__":
    main()
