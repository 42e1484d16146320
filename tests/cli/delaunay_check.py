"""Independent Delaunay check of a structure instance (.vtu read with meshio): every interior
edge (2D) / triangle (3D) is locally Delaunay — the apex of one cell is not inside the
circumcircle / circumsphere of the other.
The verdict is exact on the written doubles (Fractions); an edge whose apex lies inside counts as a
violation only beyond the rounding of the written coordinates: (r - |d - c|) / r > 1e-9, with c
and r the circumcentre and radius. Interior edges all locally Delaunay make the triangulation a
constrained Delaunay triangulation of its domain (Delaunay when the domain is convex). Prints the
edge count, the exact inside count and the largest relative depth. In 3D the depth is measured
in floating point first and decided exactly (Fractions: in-sphere sign, circumcentre) where it is
within 1e-6 of the sphere or inside.
Usage: delaunay_check.py MESH.vtu"""
import collections
import math
import sys
from fractions import Fraction

import meshio

m = meshio.read(sys.argv[1])
if "tetra" in m.cells_dict:
    import delaunay_check_3d
    sys.exit(delaunay_check_3d.main(m))
p = m.points[:, :2]
tri = m.cells_dict["triangle"]
edges = collections.defaultdict(list)
for t in tri:
    for k in range(3):
        a, b, c = int(t[k]), int(t[(k + 1) % 3]), int(t[(k + 2) % 3])
        edges[(min(a, b), max(a, b))].append(c)


def incircle_exact(a, b, c, d):
    """Sign of the incircle determinant, positive when d is inside circle abc (abc ccw)."""
    q = [[Fraction(float(v)) for v in p[i]] for i in (a, b, c, d)]
    rows = [[x - q[3][0], y - q[3][1], (x - q[3][0]) ** 2 + (y - q[3][1]) ** 2] for x, y in q[:3]]
    det = (rows[0][0] * (rows[1][1] * rows[2][2] - rows[1][2] * rows[2][1])
           - rows[0][1] * (rows[1][0] * rows[2][2] - rows[1][2] * rows[2][0])
           + rows[0][2] * (rows[1][0] * rows[2][1] - rows[1][1] * rows[2][0]))
    orient = (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0])
    return (det > 0) - (det < 0) if orient > 0 else (det < 0) - (det > 0)


def depth(a, b, c, d):
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = p[a], p[b], p[c], p[d]
    s = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / s
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / s
    r = math.hypot(ax - ux, ay - uy)
    return (r - math.hypot(dx - ux, dy - uy)) / r


interior = inside = 0
worst = 0.0
bad = []
for (a, b), apexes in edges.items():
    if len(apexes) != 2:
        continue
    interior += 1
    c, d = apexes
    if incircle_exact(a, b, c, d) > 0:
        inside += 1
        depth_ab = depth(a, b, c, d)
        worst = max(worst, depth_ab)
        if depth_ab > 1e-9:
            bad.append((a, b, depth_ab))
if bad:
    a, b, dep = max(bad, key=lambda x: x[2])
    print(f"{len(bad)} of {interior} interior edges not locally Delaunay, e.g. ({a}, {b}) at "
          f"relative depth {dep:.3g}")
    sys.exit(1)
print(f"{interior} interior edges locally Delaunay ({inside} with the apex inside by rounding only, "
      f"largest relative depth {worst:.2g})")
