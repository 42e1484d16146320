#!/usr/bin/env python3
"""Write data/explosion_glide.json: a tiny templated geometry whose boundary patch partition
explodes, to test the guard on the composition enumeration.

One geometry template, the triangle (0,0),(1,0),(0,-1) (long edge [0,1] on y = 0, apex (0,-1)),
and two instances: the identity and the glide reflection "reflect y -> -y, then translate x by
eps" with eps = 1/N (default N = 100000). The copies lie on opposite sides of y = 0 and touch along
[eps,1]x{0}, so it is a valid templated geometry. The only non-trivial template boundary mapping
T_{1,1}^{-1} o T_{1,2} is the shift (x,0) -> (x+eps,0) on [0,1-eps]x{0} (and its inverse), and
closing the interface end points under it yields the N+1 breakpoints k*eps, k = 0..N: an
enumeration of compositions must be stopped by a guard.

Usage: python3 scripts/make_explosion_structure.py [N [OUTPUT]]   (default 100000, data/explosion_glide.json)
Standard library only; deterministic.
"""
import json
import os
import sys


def build(n):
    eps = f"1/{n}"
    return {
        "symmesh": "templated-structure/1",
        "description": (
            f"Breakpoint explosion (guard test for the boundary patch partition): one geometry template, the "
            f"triangle (0,0),(1,0),(0,-1), instanced by the identity T_{{1,1}} and by the glide reflection "
            f"T_{{1,2}}: reflect y -> -y, then translate x by eps = {eps}. The copies lie on opposite sides of "
            f"y = 0 (a valid templated geometry); touching instance pairs: T_{{1,1}}/T_{{1,2}} along "
            f"[{eps},1]x{{0}}. The mapping T_{{1,1}}^{{-1}} o T_{{1,2}} is the shift (x,0) -> (x+eps,0) on "
            f"[0,1-eps]x{{0}} (its inverse the shift back on [eps,1]x{{0}}); closing the interface end points "
            f"under the mappings gives the {n + 1} breakpoints k*eps, k = 0..{n}, so the composition "
            f"enumeration must be stopped by a guard (expected: a clean 'too many breakpoints/compositions' "
            f"error, not a hang or an out-of-memory). If computed to completion: {n + 1} facet patches "
            f"({n} pieces [k*eps,(k+1)*eps] of the long edge, all in one class, plus the rest of the boundary "
            f"(0,0)-(0,-1)-(1,0) alone) and {n + 1} point patches k*eps (one class: the point k*eps admits one "
            f"more shift than the open pieces next to it); regular (every composition is a shift)."
        ),
        "dimension": 2,
        "templates": [
            {
                "name": "T",
                "kind": "geometry",
                "polygon": [["0", "0"], ["1", "0"], ["0", "-1"]],
                "instances": [
                    {"transformation": {"identity": {}}},
                    {"transformation": {"compose": [
                        {"translation": [eps, "0"]},
                        {"reflection": {"normal": ["0", "1"], "offset": "0"}},
                    ]}},
                ],
            }
        ],
    }


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100000
    if n < 2:
        sys.exit("N must be at least 2")
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.join(here, "..", "data", "explosion_glide.json")
    doc = build(n)
    t = doc["templates"][0]
    text = "\n".join([
        "{",
        f'  "symmesh": {json.dumps(doc["symmesh"])},',
        f'  "description": {json.dumps(doc["description"])},',
        f'  "dimension": {doc["dimension"]},',
        '  "templates": [',
        "    {",
        f'      "name": {json.dumps(t["name"])},',
        f'      "kind": {json.dumps(t["kind"])},',
        f'      "polygon": {json.dumps(t["polygon"])},',
        '      "instances": [',
        ",\n".join(f"        {json.dumps(i)}" for i in t["instances"]),
        "      ]",
        "    }",
        "  ]",
        "}",
    ]) + "\n"
    assert json.loads(text) == doc
    with open(out, "w", encoding="utf-8") as f:
        f.write(text)
    print(f"wrote {os.path.normpath(out)}: eps = 1/{n}")


if __name__ == "__main__":
    main()
