"""Shared fixtures: the camcov CLI to compare with, the published scenes, scratch folders.

ctest runs this suite with PYTHONPATH holding the built module and examples/, CAMCOV_BINARY
naming the CLI, and COVERAGE_SCENES_DIR the published scenes (tests on them skip without).
"""
import os
import pathlib
import subprocess

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
TEST_DATA = REPO / "tests" / "data"


@pytest.fixture(scope="session")
def cli():
    """Runs the camcov CLI: cli("run", SCENE, ...) -> CompletedProcess (text, never raises)."""
    binary = os.environ.get("CAMCOV_BINARY")
    if not binary:
        pytest.fail("CAMCOV_BINARY is not set (ctest sets it)")

    def run(*args):
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True)

    return run


@pytest.fixture(scope="session")
def published():
    """A published scene file by name, e.g. published("dynamic9")."""
    folder = os.environ.get("COVERAGE_SCENES_DIR")
    if not folder or not pathlib.Path(folder).is_dir():
        pytest.skip("COVERAGE_SCENES_DIR is not set: the published scenes are not here")
    return lambda name: str(pathlib.Path(folder) / f"{name}.json")


@pytest.fixture
def tiny():
    """Our small test scenes (tests/data/scenes)."""
    return lambda name: str(TEST_DATA / "scenes" / f"{name}.json")
