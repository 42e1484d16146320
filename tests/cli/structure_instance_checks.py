"""Independent checks of a generated structure instance, read back with meshio (Debian's
python3-meshio): cell count as reported, conforming (no edge in more than two triangles, the
boundary edges form closed curves, no two vertices at the same place), every triangle positively
oriented (counter-clockwise, spec/outputs.md#orientation), and the total signed area.
Usage: structure_instance_checks.py MESH REPORT.json EXPECTED_AREA"""
import collections
import json
import sys

import meshio
import numpy as np

mesh_path, report_path, expected_area = sys.argv[1], sys.argv[2], float(sys.argv[3])
m = meshio.read(mesh_path)
report = json.load(open(report_path))
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
