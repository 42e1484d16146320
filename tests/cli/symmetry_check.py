"""The structure instance maps onto itself under a rotation by 2*pi*k/n about the origin (3D:
about the z axis), or the reflection x -> -x with n = 0: every mapped vertex and cell centroid
lands on one of the mesh's, up to the rounding of one transformation (1e-12; points are matched
through a hash of their coordinates on a 1e-9 grid, neighbouring grid cells included).
Usage: symmetry_check.py MESH n k"""
import itertools
import math
import sys

import meshio
import numpy as np

m = meshio.read(sys.argv[1])
n, k = int(sys.argv[2]), int(sys.argv[3])
cells = m.cells_dict["tetra"] if "tetra" in m.cells_dict else m.cells_dict["triangle"]
d = 3 if "tetra" in m.cells_dict else 2
p = m.points[:, :d]
a = np.eye(d)
if n == 0:
    a[0, 0] = -1.0
else:
    c, s = math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)
    a[:2, :2] = [[c, -s], [s, c]]

GRID = 1e-9


def matched(points):
    keys = {}
    for i, q in enumerate(np.floor(points / GRID).astype(np.int64)):
        keys.setdefault(tuple(q), []).append(i)
    image = points @ a.T
    worst = 0.0
    for q, key in zip(image, np.floor(image / GRID).astype(np.int64)):
        best = math.inf
        for off in itertools.product((-1, 0, 1), repeat=d):
            for i in keys.get(tuple(key + np.array(off)), ()):
                best = min(best, float(np.max(np.abs(points[i] - q))))
        worst = max(worst, best)
    return worst


centroids = p[cells].mean(axis=1)
worst = max(matched(p), matched(centroids))
if worst > 1e-12:
    print(f"not symmetric: a mapped vertex or centroid is {worst:.3g} from the nearest one")
    sys.exit(1)
print(f"maps onto itself (largest deviation {worst:.2g})")
