"""symmesh.read_structure, .check() and .instance_graph() against `symmesh check --json`."""

import json

import networkx
import pytest

import symmesh


def test_check_equals_the_cli_report(root, cli):
    path = root / "data/fig_4_3_templated_mesh.json"
    s = symmesh.read_structure(path)
    assert (s.dimension, s.template_count, s.instance_count) == (2, 2, 5)
    report = s.check()
    code, out, _ = cli("check", "--json", path)
    assert code == 0 and report["exit_code"] == 0 and report["message"] == ""
    cli_report = json.loads(out)
    assert {k: v for k, v in report.items() if k not in ("exit_code", "message")} == cli_report
    assert report["templated_mesh"] and report["lemma_4_2"]["holds"]


def test_instance_graph_is_a_networkx_edge_list(root, cli):
    s = symmesh.read_structure(root / "data/fig_4_3_templated_mesh.json")
    edges = s.instance_graph()
    g = networkx.MultiGraph(edges)
    _, out, _ = cli("check", "--json", root / "data/fig_4_3_templated_mesh.json")
    cli_edges = json.loads(out)["instance_graph"]["edges"]
    assert g.number_of_edges() == len(cli_edges) == 10
    assert sorted(g.nodes) == [0, 1]
    # Same edges as the CLI's (1-based templates there), self-loops included.
    ours = sorted((u + 1, v + 1, a["label"]) for u, v, a in edges)
    theirs = sorted((e["templates"][0], e["templates"][1], e["label"]) for e in cli_edges)
    assert ours == theirs
    loops = [a for u, v, a in edges if a["trivial"]]
    assert len(loops) == 2 and all(a["label"] == "I" for a in loops)
    u, v, a = next(e for e in edges if e[2]["label"] == "T_{1,1} / T_{2,1}")
    assert (u, v, a["instance_a"], a["instance_b"]) == (0, 1, (0, 0), (1, 0))


def test_lemma_4_2_failure_has_the_cli_verdict_and_message(root, cli):
    path = root / "data/fig_4_4_nonconforming.json"
    report = symmesh.read_structure(path).check()
    code, _, err = cli("check", path)
    assert code == report["exit_code"] == 1
    assert not report["lemma_4_2"]["holds"] and not report["templated_mesh"]
    assert err.strip() == "symmesh: " + report["message"]


def test_a_dict_and_json_text_read_like_the_file(root):
    path = root / "data/fig_4_6_instance_graph.json"
    document = json.loads(path.read_text())
    from_file = symmesh.read_structure(str(path)).check()
    assert symmesh.read_structure(document).check() == from_file
    assert symmesh.read_structure(path.read_text()).check() == from_file


def test_regularity(root):
    assert symmesh.read_structure(root / "data/fig_4_6_instance_graph.json").check()["regular"]
    for irregular in ("data/fig_4_3_templated_mesh.json", "data/fig_4_11_irregular.json"):
        report = symmesh.read_structure(root / irregular).check()
        assert report["regular"] is False and report["irregularity"], irregular


def test_built_in_examples():
    assert "bridge" in symmesh.example_names()
    bridge = symmesh.example("bridge")
    assert (bridge.template_count, bridge.instance_count) == (2, 48)
    assert bridge.check()["templated_geometry"]


@pytest.mark.parametrize("name", ["malformed", "missing_field", "nan", "unknown_transformation"])
def test_bad_files_raise_the_cli_message(root, cli, name):
    path = root / f"tests/data/bad/{name}.json"
    code, _, err = cli("check", path)
    assert code == 2
    with pytest.raises(symmesh.InputError) as e:
        symmesh.read_structure(path).check()
    assert isinstance(e.value, ValueError)
    assert err.strip() == f"symmesh: error: {e.value}"


def test_missing_file_and_unknown_example(root, cli):
    code, _, err = cli("check", root / "no/such.json")
    with pytest.raises(symmesh.InputError) as e:
        symmesh.read_structure(root / "no/such.json")
    assert code == 2 and err.strip() == f"symmesh: error: {e.value}"
    with pytest.raises(symmesh.InputError, match="unknown example 'nope'"):
        symmesh.example("nope")


def test_not_a_templated_structure(root, cli):
    path = root / "tests/data/bad/overlapping_instances.json"
    report = symmesh.read_structure(path).check()
    code, _, err = cli("check", path)
    assert code == report["exit_code"] == 2 and not report["templated_structure"]
    assert err.strip().endswith(report["message"])
