"""symmesh.generate against `symmesh generate --report`: the same cells, the same files, the same
refusals; the returned meshes are meshio.Mesh objects that meshio writes and reads back."""

import meshio
import numpy
import pytest

import symmesh

CELL_DATA = ("region", "template", "instance")


def counts(g):
    return g.report["cells_structure_instance"], g.report["cells_templates"]


@pytest.mark.parametrize("data,options,kwargs", [
    ("data/ngon_slice_8.json", ("--size", "0.1"), dict(size=0.1)),
    ("data/ngon_slice_8.json", ("--size", "0.08", "--min-angle", "25", "--method", "conventional"),
     dict(size=0.08, min_angle=25, method="conventional")),
    ("data/fig_6_8_multiregion_rotational.json", ("--size", "0.2", "--method", "bpp"),
     dict(size=0.2, method="bpp")),
])
def test_2d_cell_counts_equal_the_cli_report(root, cli_report, data, options, kwargs):
    report, cli_vtu = cli_report(root / data, *options)
    g = symmesh.generate(symmesh.read_structure(root / data), **kwargs)
    templated, at = g
    assert g.method == report["method"]
    assert len(at.cells_dict["triangle"]) == report["cells_structure_instance"] == g.cell_count
    assert len(at.points) == report["vertices_structure_instance"]
    assert len(templated.cells_dict["triangle"]) == report["cells_templates"]
    assert len(g.instances) == report["instances"] and len(g.templates) == report["templates"]
    for key in ("cells_structure_instance", "cells_templates", "bytes_mesh", "bytes_templated"):
        assert g.report[key] == report[key], key
    # The arrays are what the CLI's .vtu holds.
    written = meshio.read(cli_vtu)
    numpy.testing.assert_array_equal(written.cells_dict["triangle"], at.cells_dict["triangle"])
    numpy.testing.assert_allclose(written.points[:, :2], at.points[:, :2], rtol=0, atol=0)
    for key in CELL_DATA:
        numpy.testing.assert_array_equal(written.cell_data[key][0], at.cell_data[key][0])


def test_3d_cell_counts_equal_the_cli_report(root, cli_report):
    path = root / "data/rotational_slice_3d.json"
    report, _ = cli_report(path, "--size", "0.3")
    g = symmesh.generate(path, size=0.3)
    templated, at = g
    assert counts(g) == (report["cells_structure_instance"], report["cells_templates"])
    assert len(at.cells_dict["tetra"]) == report["cells_structure_instance"]
    assert len(templated.cells_dict["tetra"]) == report["cells_templates"]
    assert set(numpy.unique(at.cell_data["template"][0])) == set(range(1, len(g.templates) + 1))
    assert len(numpy.unique(at.cell_data["instance"][0])) == report["instances"]


def test_3d_no_repair_is_the_cli_no_repair(root, cli_report):
    # generate(..., repair=False) is `--no-repair` (spec/generation.md#outlier-repair): the same
    # cells as the CLI with it, and no outlier_repair in the report; by default the repair runs.
    path = root / "data/rotational_slice_3d.json"
    report, _ = cli_report(path, "--size", "0.3", "--no-repair")
    plain = symmesh.generate(path, size=0.3, repair=False)
    assert counts(plain) == (report["cells_structure_instance"], report["cells_templates"])
    assert "outlier_repair" not in plain.report and "outlier_repair" not in report
    assert "outlier_repair" in symmesh.generate(path, size=0.3).report


def test_meshio_writes_and_reads_the_returned_meshes(root, tmp_path):
    templated, at = symmesh.generate(root / "data/ngon_slice_8.json", size=0.1)
    for mesh, name in ((at, "at.vtu"), (templated, "templated.vtu"), (at, "at.msh")):
        mesh.write(tmp_path / name) if not name.endswith(".msh") else \
            meshio.write(tmp_path / name, mesh, file_format="gmsh22", binary=False)
        back = meshio.read(tmp_path / name)
        assert len(back.cells_dict["triangle"]) == len(mesh.cells_dict["triangle"])
        numpy.testing.assert_allclose(back.points[:, :2], mesh.points[:, :2])
    back = meshio.read(tmp_path / "at.vtu")
    for key in CELL_DATA:
        numpy.testing.assert_array_equal(back.cell_data[key][0], at.cell_data[key][0])


def test_structure_instance_is_the_instances_applied_to_the_templates(root):
    g = symmesh.generate(root / "data/ngon_slice_8.json", size=0.1)
    at, templates = g.structure_instance, g.templates
    cells, instance = at.cells_dict["triangle"], at.cell_data["instance"][0]
    offset = 0
    for k, inst in enumerate(g.instances, start=1):
        t = templates[inst["template"]]
        mine = cells[instance == k]
        assert len(mine) == len(t.cells_dict["triangle"])
        # Every AT point of the instance is its transformation applied to a template point.
        mapped = t.points[:, :2] @ inst["matrix"].T + inst["translation"]
        for p in at.points[numpy.unique(mine), :2]:
            assert numpy.min(numpy.linalg.norm(mapped - p, axis=1)) < 1e-12
        offset += len(mine)
    assert offset == len(cells)


def test_write_gives_the_cli_bytes(root, cli_report, tmp_path):
    path = root / "data/ngon_slice_8.json"
    _, cli_vtu = cli_report(path, "--size", "0.1")
    g = symmesh.generate(path, size=0.1)
    g.write(tmp_path / "api.vtu")
    assert (tmp_path / "api.vtu").read_bytes() == cli_vtu.read_bytes()
    g.write_templated(tmp_path / "api.tmesh")
    assert (tmp_path / "api.tmesh").stat().st_size > 0
    with pytest.raises(symmesh.InputError, match="unknown mesh file extension"):
        g.write(tmp_path / "api.obj")


@pytest.mark.parametrize("data,options,kwargs", [
    ("data/ngon_slice_8.json", ("--size", "-1"), dict(size=-1)),
    ("data/ngon_slice_8.json", ("--size", "0.1", "--min-angle", "40"), dict(size=0.1, min_angle=40)),
    ("data/ngon_slice_8.json", ("--size", "0.1", "--method", "frobnicate"),
     dict(size=0.1, method="frobnicate")),
    ("data/ngon_slice_8.json", ("--size", "0.1", "--method", "reflective"),
     dict(size=0.1, method="reflective")),
    ("data/ngon_slice_8.json", ("--size", "0.0001", "--max-cells", "1000"),
     dict(size=0.0001, max_cells=1000)),
    ("data/fig_4_3_templated_mesh.json", ("--size", "0.1"), dict(size=0.1)),
    ("tests/data/bad/malformed.json", ("--size", "0.1"), dict(size=0.1)),
])
def test_refusals_raise_the_cli_message(root, cli, tmp_path, data, options, kwargs):
    code, _, err = cli("generate", root / data, *options, "-o", tmp_path / "x.vtu")
    assert code == 2
    with pytest.raises(symmesh.InputError) as e:
        symmesh.generate(root / data, **kwargs)
    assert err.strip() == f"symmesh: error: {e.value}"
    assert not (tmp_path / "x.vtu").exists()
