"""Resuming a Python batch: the same code is reused and says so; changed code is refused (or,
with force, run again), never answered with the old numbers."""
import importlib.util
import json

import pytest

import camcov

SHORT = {"sim.duration": 2.0}


def load_controller(folder, turn_rate):
    """Writes mine.py (every camera turns at `turn_rate`) and returns its factory."""
    source = folder / "mine.py"
    source.write_text(
        "import numpy as np\n"
        f"TURN = {turn_rate!r}\n"
        "def make(scene, params, seed):\n"
        "    return lambda o: np.tile([0.0, 0.0, TURN], (len(o.cameras), 1))\n")
    spec = importlib.util.spec_from_file_location("mine", source)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.make


def test_a_changed_python_controller_is_refused_then_run_again_with_force(tiny, tmp_path, capsys):
    scene = tiny("tiny_static")
    out = str(tmp_path / "batch")
    options = dict(methods=["local"], seeds=1, out=out, params=SHORT, explorer="none",
                   report=False)
    first = camcov.bench([scene], controllers={"mine": load_controller(tmp_path, 0.5)}, **options)
    run_file = tmp_path / "batch" / "runs" / "tiny_static-mine-seed1.json"
    old_run = run_file.read_bytes()
    capsys.readouterr()

    again = camcov.bench([scene], controllers={"mine": load_controller(tmp_path, 0.5)}, **options)
    assert again == first
    assert "2 of 2 jobs already done in " + out in capsys.readouterr().err

    changed = load_controller(tmp_path, 0.75)
    with pytest.raises(camcov.InputError, match=r"mine \(python \w+ then, python \w+ now\)"):
        camcov.bench([scene], controllers={"mine": changed}, **options)
    camcov.bench([scene], controllers={"mine": changed}, force=True, **options)
    assert run_file.read_bytes() != old_run, "the changed controller ran again"
    assert "1 of 2 jobs already done" in capsys.readouterr().err, "local's run is kept"
    batch = json.loads((tmp_path / "batch" / "batch.json").read_text())
    assert batch["methodIdentities"]["mine"].startswith("python ")
    assert batch["methodIdentities"]["local"].startswith("c++ ")
    assert batch["command"][0] == "python"
    assert batch["command"][1].endswith("pytest/__main__.py"), "the script that ran the batch"


def test_a_python_methods_version_is_part_of_its_identity(tiny, tmp_path):
    scene = tiny("tiny_static")
    factory = load_controller(tmp_path, 0.5)
    options = dict(methods=["local"], seeds=1, out=str(tmp_path / "b"), params=SHORT,
                   explorer="none", report=False)
    factory.version = "1"
    camcov.bench([scene], controllers={"mine": factory}, **options)
    factory.version = "2"
    with pytest.raises(camcov.InputError, match="version 1 then, python [0-9a-f]+ version 2 now"):
        camcov.bench([scene], controllers={"mine": factory}, **options)
