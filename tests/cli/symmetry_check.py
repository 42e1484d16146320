"""The structure instance maps onto itself under a rotation by 2*pi*k/n about the origin (or the
reflection x -> -x with n = 0): every rotated vertex and triangle centroid lands on one of the
mesh's, up to the rounding of one transformation (1e-12). Usage: symmetry_check.py MESH n k"""
import math
import sys

import meshio
import numpy as np

m = meshio.read(sys.argv[1])
n, k = int(sys.argv[2]), int(sys.argv[3])
p = m.points[:, :2]
tri = m.cells_dict["triangle"]
if n == 0:
    a = np.array([[-1.0, 0.0], [0.0, 1.0]])
else:
    c, s = math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n)
    a = np.array([[c, -s], [s, c]])


def matched(points):
    image = points @ a.T
    order = np.lexsort((points[:, 1], points[:, 0]))
    ref = points[order]
    worst = 0.0
    for q in image:
        d = np.min(np.max(np.abs(ref - q), axis=1))
        worst = max(worst, d)
    return worst


centroids = p[tri].mean(axis=1)
worst = max(matched(p), matched(centroids))
if worst > 1e-12:
    print(f"not symmetric: a mapped vertex or centroid is {worst:.3g} from the nearest one")
    sys.exit(1)
print(f"maps onto itself (largest deviation {worst:.2g})")
