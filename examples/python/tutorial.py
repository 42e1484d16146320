"""symmesh from Python, cell by cell (docs/api.md#python). Run it as a script or cell by cell in
an editor that knows "# %%" cells:

    PYTHONPATH=build/python /usr/bin/python3 examples/python/tutorial.py [OUTPUT_DIR]

It writes everything into OUTPUT_DIR (default: tutorial-out) and stops with an error at the first
result that is not what the text says (ctest runs it: python.tutorial)."""

# %% [markdown]
# ## 1. A templated geometry, written by hand
# A ring of four L-shaped slices around the origin: one geometry template (its boundary polygon,
# exact numbers as strings) instanced by the rotations by 0, 90, 180 and 270 degrees, and a square
# cap translated into the first slice's notch, in a second region. The format is
# docs/input-format.md; the same dict could be read from a .json file.

# %%
import pathlib
import sys

import meshio
import networkx

import symmesh

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "tutorial-out")
out.mkdir(parents=True, exist_ok=True)

rotation = [{"transformation": {"rotation": {"order": 4, "k": k}}} for k in range(4)]
document = {
    "symmesh": "templated-structure/1",
    "dimension": 2,
    "templates": [
        {"name": "L", "kind": "geometry",
         "polygon": [["0", "0"], ["2", "0"], ["2", "1"], ["1", "1"], ["1", "2"], ["0", "2"]],
         "instances": rotation},
        {"name": "cap", "kind": "geometry",
         "polygon": [["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]],
         "instances": [{"transformation": {"translation": ["1", "1"]}, "region": 2}]},
    ],
}
structure = symmesh.read_structure(document)
print(structure)

# %% [markdown]
# ## 2. Check it
# `check()` is `symmesh check --json` as a dict: Eq. 4.2 (the instances do not overlap), the kind
# of structure, the Lemma 4.2 verdict for mesh templates, and the regularity of the instance graph
# (Definition 4.9).

# %%
report = structure.check()
print({k: report[k] for k in ("templated_structure", "templated_geometry", "regular")})
assert report["templated_structure"] and report["templated_geometry"] and report["exit_code"] == 0

# %% [markdown]
# ## 3. Its instance graph
# One node per template, one edge per pair of neighbouring instances, one self-loop per template:
# a networkx multigraph.

# %%
graph = networkx.MultiGraph(structure.instance_graph())
names = dict(enumerate(structure.template_names))
for u, v, label in sorted(graph.edges(data="label")):
    print(f"  {names[u]} -- {names[v]}: {label}")
assert graph.number_of_edges() == report["instance_graph_edges"]
assert graph.number_of_edges(0, 1) == 1  # the cap sits in the notch of the first L only

# %% [markdown]
# ## 4. Generate a templated mesh
# Algorithm 5.6 over the boundary patch partition, certified by Lemma 4.2. The result unpacks into
# the templated mesh (every template once) and the structure instance AT, both meshio.Mesh objects
# with cell data region, template and instance.

# %%
result = symmesh.generate(structure, size=0.25, min_angle=25)
templated, instance = result
triangles = len(instance.cells_dict["triangle"])
print(result, "-", result.report["instances"], "instances")
assert triangles == result.report["cells_structure_instance"]
assert len(templated.cells_dict["triangle"]) == result.report["cells_templates"] < triangles
assert set(instance.cell_data["region"][0]) == {1, 2}

# %% [markdown]
# ## 5. Write it
# meshio writes the returned meshes in any format it knows; `write()` is `generate -o` (binary .vtu
# with cell data, Gmsh .msh 4.1, Medit .mesh), and `write_templated()` the .tmesh file that
# `symmesh solve` reads.

# %%
meshio.write(out / "tutorial_instance.vtu", instance)
meshio.write(out / "tutorial_templates.vtu", templated)
result.write(out / "tutorial.msh")
result.write_templated(out / "tutorial.tmesh")
assert len(meshio.read(out / "tutorial.msh").cells_dict["triangle"]) == triangles

# %% [markdown]
# ## 6. Built-in objects, 3D, and errors
# Every object of `symmesh example --list` is one call away; 3D works the same (TetGen per
# template). Bad input raises symmesh.InputError (a ValueError) with the command's message.

# %%
tsv = symmesh.generate(symmesh.example("tsv-8"), size=0.4)
print(tsv)
assert len(tsv.structure_instance.cells_dict["tetra"]) == tsv.report["cells_structure_instance"]
try:
    symmesh.generate(structure, size=0.25, method="rotational")
except symmesh.InputError as e:
    print("refused:", e)
else:
    raise AssertionError("the rotational method took a structure with a cap")
print("tutorial: wrote", ", ".join(sorted(p.name for p in out.iterdir())))
