"""symmesh: symmetry-aware volumetric meshing with templated structures (docs/api.md#python).

    import symmesh
    s = symmesh.read_structure("data/fig_4_3_templated_mesh.json")   # or a dict, or JSON text
    s.check()["lemma_4_2"]["holds"]          # the report of `symmesh check --json`
    s.instance_graph()                       # [(u, v, attrs), ...] for networkx.MultiGraph
    g = symmesh.generate(symmesh.example("ngon-slice-8"), size=0.1)
    templated, instance = g                  # two meshio.Mesh objects
    instance.cell_data["region"]             # also "template", "instance"

Every function runs the same C++ code as the `symmesh` command, and every refusal raises with
the message the command prints after "symmesh: error: ": InputError (a ValueError) for bad input,
CertificateError (a RuntimeError) when a generated mesh fails its Lemma 4.2 certificate.
"""

import functools
import json
import os

import meshio
import numpy

from . import _symmesh
from ._symmesh import CertificateError, InputError

__version__ = _symmesh.__version__
__all__ = [
    "CertificateError",
    "Generation",
    "InputError",
    "Structure",
    "example",
    "example_names",
    "generate",
    "read_structure",
]

_CELL_TYPE = {2: "triangle", 3: "tetra"}


class Structure:
    """A templated structure, read and validated in shape (spec/input-format.md)."""

    def __init__(self, handle):
        self._handle = handle
        self._checked = None

    dimension = property(lambda self: self._handle.dimension)
    template_count = property(lambda self: self._handle.template_count)
    instance_count = property(lambda self: self._handle.instance_count)
    template_names = property(lambda self: self._handle.template_names)
    source = property(lambda self: self._handle.source)
    kernel = property(lambda self: self._handle.kernel)

    def _check(self):
        # The exact analysis runs once per structure (it is immutable).
        if self._checked is None:
            self._checked = self._handle.check()
        return self._checked

    def check(self):
        """The `symmesh check --json` report as a dict, plus "exit_code" (what the command exits
        with: 0 templated mesh or geometry, 1 templated structure only, 2 not a templated
        structure) and "message" (its error line, else ""). Raises InputError when the structure
        is not well-formed."""
        c = self._check()
        report = json.loads(c["report"])
        report["exit_code"] = c["exit_code"]
        report["message"] = c["message"]
        return report

    def instance_graph(self):
        """The instance graph (Section 4.2) as a list of edges (u, v, attrs): u and v are 0-based
        template indices (names in template_names), attrs holds "label", "trivial" (the
        reflexive self-loop) and "instance_a"/"instance_b" as 0-based (template, instance).
        networkx.MultiGraph(structure.instance_graph()) builds the multigraph."""
        return [(u, v, dict(attrs)) for u, v, attrs in self._check()["edges"]]

    def __repr__(self):
        return (f"<symmesh.Structure {self.source!r}: {self.dimension}D, "
                f"{self.template_count} templates, {self.instance_count} instances>")


def read_structure(path_or_dict):
    """A templated structure from a file path, a dict (the JSON document) or JSON text."""
    if isinstance(path_or_dict, dict):
        return Structure(_symmesh.Structure.parse(json.dumps(path_or_dict), "input"))
    if isinstance(path_or_dict, str) and path_or_dict.lstrip().startswith("{"):
        return Structure(_symmesh.Structure.parse(path_or_dict, "input"))
    return Structure(_symmesh.Structure.read(os.fspath(path_or_dict)))


def example(name):
    """A built-in object of `symmesh example NAME` (spec/examples.md)."""
    return Structure(_symmesh.Structure.example(name))


def example_names():
    return _symmesh.Structure.example_names()


def _meshio(d, **extra_cell_data):
    cell_data = {k: [numpy.asarray(d[k])] for k in ("region", "template", "instance")}
    return meshio.Mesh(d["points"], [(_CELL_TYPE[d["dimension"]], d["cells"])],
                       cell_data=cell_data)


class Generation:
    """A generated, certified templated mesh. Unpacks as (templated, structure_instance)."""

    def __init__(self, handle):
        self._handle = handle
        self.method = handle.method
        self.report = json.loads(handle.report_json)

    @functools.cached_property
    def structure_instance(self):
        """AT(X) as a meshio.Mesh, as the .vtu that write() makes holds it: cell data region,
        template and instance (global, template-major), the last two numbered from 1."""
        return _meshio(self._handle.structure_instance())

    @functools.cached_property
    def _templated(self):
        return self._handle.templated_mesh()

    @functools.cached_property
    def templated(self):
        """The templated mesh as one meshio.Mesh: every template once, in its own coordinates,
        one after the other; cell data template (from 1), and region and instance -1 (a template
        cell belongs to all instances of its template: see instances)."""
        t = self._templated
        points, cells, offset = [], [], 0
        for m in t["templates"]:
            points.append(m["points"])
            cells.append(m["cells"] + offset)
            offset += len(m["points"])
        merged = {k: numpy.concatenate([m[k] for m in t["templates"]])
                  for k in ("region", "template", "instance")}
        merged.update(dimension=t["dimension"], points=numpy.concatenate(points),
                      cells=numpy.concatenate(cells))
        return _meshio(merged)

    @property
    def templates(self):
        """One meshio.Mesh per template, in its own coordinates."""
        return [_meshio(m) for m in self._templated["templates"]]

    @property
    def instances(self):
        """Per instance (global order; cell data instance k is instances[k - 1]): {"template"
        (0-based index into templates), "region", "matrix", "translation"}, the instance being
        x -> matrix @ x + translation applied to its template."""
        return self._templated["instances"]

    @property
    def cell_count(self):
        return self._handle.cell_count

    def write(self, path, ascii=False, compress=False):
        """The structure instance as .vtu, .msh or .mesh, as `generate -o` writes it."""
        self._handle.write(os.fspath(path), ascii, compress)

    def write_templated(self, path):
        """The templated mesh as .tmesh (spec/outputs.md#tmesh)."""
        self._handle.write_templated(os.fspath(path))

    def __iter__(self):
        return iter((self.templated, self.structure_instance))

    def __repr__(self):
        return (f"<symmesh.Generation {self.method}: {self.cell_count} cells from "
                f"{self.report['cells_templates']} template cells>")


def generate(structure, size, min_angle=20.0, method="auto", max_cells=0, progress=False,
             repair=True):
    """`symmesh generate`: a templated mesh of a templated geometry (Algorithm 5.6 in 2D, 5.7 in
    3D, or a baseline), certified by Lemma 4.2. `structure` is a Structure or anything
    read_structure takes; repair=False is `--no-repair` (3D: TetGen's tetrahedra kept as they
    are). Raises InputError or CertificateError with the CLI's message."""
    if not isinstance(structure, Structure):
        structure = read_structure(structure)
    return Generation(_symmesh.Generation(structure._handle, float(size), float(min_angle),
                                          str(method), float(max_cells), bool(progress),
                                          bool(repair)))
