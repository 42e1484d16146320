"""The 3D part of delaunay_check.py: every triangle shared by two tetrahedra is locally Delaunay
(the apex of one tetrahedron is not inside the circumsphere of the other). A candidate found in
floating point (relative depth above -1e-6, or a tetrahedron too flat for a floating
circumcentre) is decided exactly on the written doubles (Fractions): the sign of the in-sphere
determinant D = det[q_i - e, |q_i - e|^2] (q_i the tetrahedron's corners, e the apex). Inside is
a violation only beyond the rounding of the written coordinates, measured as |D| / L^5 with L
the largest distance among the five points: a perturbation of the coordinates by that fraction
of L can change the sign. (The relative depth of the apex is no measure for the slivers a
Delaunay tetrahedralization of cospherical points contains — four nearly cocircular points,
whose circumsphere the rounding moves anywhere — while D scales with the volume.) The
threshold 1e-9 matches a relative depth of about 1e-8 for a well-shaped tetrahedron."""
import collections
import math
from fractions import Fraction

import numpy as np


def circumcentre_exact(q):
    """Exact circumcentre of four points (Fractions): solves 2 (q_i - q_0) . c = |q_i|^2 - |q_0|^2."""
    rows = []
    for i in (1, 2, 3):
        rows.append([2 * (q[i][k] - q[0][k]) for k in range(3)] +
                    [sum(q[i][k] ** 2 - q[0][k] ** 2 for k in range(3))])
    for col in range(3):  # Gaussian elimination with exact pivots
        piv = next(r for r in range(col, 3) if rows[r][col] != 0)
        rows[col], rows[piv] = rows[piv], rows[col]
        for r in range(3):
            if r != col and rows[r][col] != 0:
                f = rows[r][col] / rows[col][col]
                rows[r] = [a - f * b for a, b in zip(rows[r], rows[col])]
    return [rows[k][3] / rows[k][k] for k in range(3)]


def det3(m):
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def det4(m):
    return sum((-1) ** j * m[0][j] * det3([[m[i][k] for k in range(4) if k != j] for i in (1, 2, 3)])
               for j in range(4))


def exact_depth(p, tet, d):
    """None when apex d is not strictly inside the circumsphere of tet (exact), else |D| / L^5."""
    q = [[Fraction(float(v)) for v in p[i]] for i in tet]
    e = [Fraction(float(v)) for v in p[d]]
    rows = [[x[k] - e[k] for k in range(3)] for x in q]
    lifted = [r + [sum(v * v for v in r)] for r in rows]
    orient = det3([[q[i][k] - q[0][k] for k in range(3)] for i in (1, 2, 3)])
    big_d = det4(lifted)
    # For a positive tetrahedron, e is inside its circumsphere when det4 < 0 in this row order.
    inside = big_d < 0 if orient > 0 else big_d > 0
    if not inside:
        return None
    pts = [[float(v) for v in x] for x in q + [e]]
    span = max(math.dist(a, b) for a in pts for b in pts)
    return abs(float(big_d)) / span ** 5


def main(m):
    p = m.points[:, :3].astype(float)
    tet = m.cells_dict["tetra"]
    faces = collections.defaultdict(list)
    for t, c in enumerate(tet):
        for k in range(4):
            f = tuple(sorted(int(c[j]) for j in range(4) if j != k))
            faces[f].append((t, int(c[k])))
    interior = inside = 0
    worst = 0.0
    bad = []
    pairs = [(v[0][0], v[1][1]) for v in faces.values() if len(v) == 2]
    pairs += [(v[1][0], v[0][1]) for v in faces.values() if len(v) == 2]
    interior = len(pairs) // 2
    if pairs:
        t_idx = np.array([a for a, _ in pairs])
        d_idx = np.array([b for _, b in pairs])
        x = p[tet[t_idx]]  # (n, 4, 3)
        a = x[:, 1:] - x[:, :1]
        rhs = 0.5 * (np.sum(x[:, 1:] ** 2, axis=2) - np.sum(x[:, :1] ** 2, axis=2))
        scale = np.max(np.abs(a), axis=(1, 2))
        det = np.linalg.det(a)
        # Flat to rounding: no floating circumcentre; decided exactly below.
        flat = ~(np.abs(det) > 1e-12 * scale ** 3)
        depth = np.full(len(pairs), np.inf)
        ok = np.nonzero(~flat)[0]
        with np.errstate(all="ignore"):
            c = np.linalg.solve(a[ok], rhs[ok][..., None])[..., 0]
            r = np.linalg.norm(x[ok, 0] - c, axis=1)
            depth[ok] = (r - np.linalg.norm(p[d_idx[ok]] - c, axis=1)) / r
        candidates = np.nonzero(~(depth < -1e-6))[0]
        for k in candidates:
            dep = exact_depth(p, tet[t_idx[k]], int(d_idx[k]))
            if dep is None:
                continue
            inside += 1
            worst = max(worst, dep)
            if dep > 1e-9:
                bad.append((tuple(int(v) for v in tet[t_idx[k]]), int(d_idx[k]), dep))
    if bad:
        t, d, dep = max(bad, key=lambda b: b[2])
        print(f"{len(bad)} of {interior} interior triangles not locally Delaunay, e.g. apex {d} "
              f"inside the circumsphere of {t}, |D| / L^5 = {dep:.3g}")
        return 1
    print(f"{interior} interior triangles locally Delaunay ({inside} with the apex inside by "
          f"rounding only, largest |D| / L^5 {worst:.2g})")
    return 0
