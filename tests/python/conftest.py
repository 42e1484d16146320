"""Fixtures of the Python module's tests (docs/api.md#python): the source tree, and the CLI whose
report and messages the module must reproduce. ctest sets SYMMESH_SOURCE_DIR and SYMMESH_CLI, and
PYTHONPATH to the built package."""

import json
import os
import pathlib
import subprocess

import pytest


@pytest.fixture(scope="session")
def root():
    return pathlib.Path(os.environ.get("SYMMESH_SOURCE_DIR",
                                       pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def cli():
    """Runs `symmesh ARGS...`; returns (exit code, stdout, stderr)."""
    binary = os.environ.get("SYMMESH_CLI")
    if not binary:
        pytest.skip("SYMMESH_CLI is not set (ctest sets it)")

    def run(*args, cwd=None):
        p = subprocess.run([binary, *map(str, args)], capture_output=True, text=True, cwd=cwd,
                           check=False)
        return p.returncode, p.stdout, p.stderr

    return run


@pytest.fixture(scope="session")
def cli_report(cli, tmp_path_factory):
    """The `generate --report` JSON of the CLI for the same input and options."""

    def report(path, *options):
        out = tmp_path_factory.mktemp("cli")
        code, _, err = cli("generate", path, *options, "-o", out / "at.vtu",
                           "--report", out / "report.json", "--quiet")
        assert code == 0, err
        return json.loads((out / "report.json").read_text()), out / "at.vtu"

    return report
