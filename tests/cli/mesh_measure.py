"""Prints the volume of a tetrahedral mesh and the area of its boundary triangles (those in one
tetrahedron), read with meshio: the reference an adapted mesh of the same object must keep.
Usage: mesh_measure.py MESH.vtu"""
import collections
import sys

import meshio
import numpy as np

m = meshio.read(sys.argv[1])
p = m.points[:, :3]
tet = m.cells_dict["tetra"]
a, b, c, d = (p[tet[:, k]] for k in range(4))
volume = np.einsum("ij,ij->i", np.cross(b - a, c - a), d - a).sum() / 6
faces = collections.Counter()
for t in tet:
    for f in ((t[0], t[1], t[2]), (t[0], t[1], t[3]), (t[0], t[2], t[3]), (t[1], t[2], t[3])):
        faces[tuple(sorted(f))] += 1
area = 0.0
for f, n in faces.items():
    if n == 1:
        area += np.linalg.norm(np.cross(p[f[1]] - p[f[0]], p[f[2]] - p[f[0]])) / 2
print(repr(float(volume)), repr(float(area)))
