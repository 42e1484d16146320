#!/usr/bin/env python3
"""A clone merged back by `symmesh adapt` (tests/cli/test_adapt.sh, spec/adaptation.md#tmesh-cloning).

usage: merged_back_check.py BASE REFUSED REFUSED_KEY MERGED MESSAGE

BASE.REFUSED.json is the report of a run whose first step (REFUSED_KEY) must merge nothing;
BASE.MERGED.json of a --merge-congruent run that must merge exactly one template, leaving as many
templates as BASE.0.tmesh has; and BASE.MERGED.vtu must hold the cells of BASE.0.vtu, as point
sets with coordinates rounded to 1e-9 (read by meshio). Exits non-zero with MESSAGE otherwise.
"""
import json
import sys

import meshio
import numpy as np


def cells(path):
    m = meshio.read(path)
    return sorted(tuple(sorted(tuple(np.round(m.points[v], 9)) for v in c)) for c in m.cells[0].data)


def main():
    base, refused, refused_key, merged, message = sys.argv[1:6]
    r, m = (json.load(open(f"{base}.{k}.json")) for k in (refused, merged))
    nt = len(json.load(open(f"{base}.0.tmesh"))["templates"])
    assert r["steps"][0][refused_key] == 0, r["steps"]
    assert m["steps"][0] == {"merge_congruent": 1, "templates": nt}, m["steps"]
    assert cells(f"{base}.{merged}.vtu") == cells(f"{base}.0.vtu"), message


if __name__ == "__main__":
    main()
