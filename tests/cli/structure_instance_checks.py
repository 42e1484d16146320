"""Independent checks of a generated structure instance, read back with meshio (Debian's
python3-meshio): cell count as reported, conforming (2D: no edge in more than two triangles, the
boundary edges form closed curves; 3D: no triangle in more than two tetrahedra, the boundary
triangles form closed surfaces; both: no two vertices at the same place), every cell positively
oriented (counter-clockwise triangles, positive-volume tetrahedra, spec/outputs.md#orientation),
and the total signed area (2D) or volume (3D).
In 3D an interface that does not conform leaves its triangles on the boundary of both sides, so
the area of the boundary triangles is checked against EXPECTED_SURFACE_AREA when given.
Usage: structure_instance_checks.py MESH REPORT.json EXPECTED_AREA_OR_VOLUME [EXPECTED_SURFACE_AREA]"""
import collections
import json
import sys

import meshio
import numpy as np

mesh_path, report_path, expected_area = sys.argv[1], sys.argv[2], float(sys.argv[3])
m = meshio.read(mesh_path)
report = json.load(open(report_path))


def check_tetrahedra():
    tet = m.cells_dict["tetra"]
    p = m.points[:, :3]
    problems = []
    if len(tet) != report["cells_structure_instance"]:
        problems.append(f"{len(tet)} cells, report says {report['cells_structure_instance']}")
    faces = collections.Counter()
    for t in tet:
        for f in ((t[0], t[1], t[2]), (t[0], t[1], t[3]), (t[0], t[2], t[3]), (t[1], t[2], t[3])):
            faces[tuple(sorted(f))] += 1
    if any(c > 2 for c in faces.values()):
        problems.append("a triangle lies in more than two tetrahedra")
    boundary_edges = collections.Counter()
    for f, c in faces.items():
        if c == 1:
            for a, b in ((f[0], f[1]), (f[1], f[2]), (f[0], f[2])):
                boundary_edges[(a, b)] += 1
    if len(sys.argv) > 4:
        bf = np.array([f for f, c in faces.items() if c == 1])
        surface = 0.5 * np.linalg.norm(np.cross(p[bf[:, 1]] - p[bf[:, 0]], p[bf[:, 2]] - p[bf[:, 0]]),
                                       axis=1).sum()
        expected_surface = float(sys.argv[4])
        if abs(surface - expected_surface) > 1e-9 * max(1.0, expected_surface):
            problems.append(f"boundary area {surface}, expected {expected_surface} (an interface "
                            "does not conform)")
    if any(c % 2 for c in boundary_edges.values()):
        problems.append("the boundary triangles do not form closed surfaces (hanging vertex)")
    if len(np.unique(np.round(p, 12), axis=0)) != len(p):
        problems.append("two vertices at the same place (not identified)")
    a = p[tet[:, 0]]
    signed = np.einsum("ij,ij->i", p[tet[:, 1]] - a,
                       np.cross(p[tet[:, 2]] - a, p[tet[:, 3]] - a)) / 6
    if (signed <= 0).any():
        problems.append(f"{int((signed <= 0).sum())} of {len(tet)} tetrahedra have no positive volume")
    volume = signed.sum()
    if abs(volume - expected_area) > 1e-9 * max(1.0, expected_area):
        problems.append(f"volume {volume}, expected {expected_area}")
    if problems:
        print("; ".join(problems))
        sys.exit(1)
    print(f"{len(tet)} tetrahedra, conforming, all positive, volume {volume:.12g}")
    sys.exit(0)


if "tetra" in m.cells_dict:
    check_tetrahedra()
tri = m.cells_dict["triangle"]
p = m.points[:, :2]
problems = []
if len(tri) != report["cells_structure_instance"]:
    problems.append(f"{len(tri)} cells, report says {report['cells_structure_instance']}")
edges = collections.Counter()
for t in tri:
    for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
        edges[(min(a, b), max(a, b))] += 1
if any(c > 2 for c in edges.values()):
    problems.append("an edge lies in more than two triangles")
degree = collections.Counter()
for (a, b), c in edges.items():
    if c == 1:
        degree[a] += 1
        degree[b] += 1
if any(d % 2 for d in degree.values()):
    problems.append("the boundary edges do not form closed curves (hanging vertex)")
if len(np.unique(np.round(p, 12), axis=0)) != len(p):
    problems.append("two vertices at the same place (not identified)")
signed = 0.5 * np.cross(p[tri[:, 1]] - p[tri[:, 0]], p[tri[:, 2]] - p[tri[:, 0]])
if (signed <= 0).any():
    problems.append(f"{int((signed <= 0).sum())} of {len(tri)} triangles are not counter-clockwise")
area = signed.sum()
if abs(area - expected_area) > 1e-9 * max(1.0, expected_area):
    problems.append(f"area {area}, expected {expected_area}")
if problems:
    print("; ".join(problems))
    sys.exit(1)
print(f"{len(tri)} triangles, conforming, all counter-clockwise, area {area:.12g}")
