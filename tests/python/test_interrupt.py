"""Ctrl-C (SIGINT) stops camcov's long calls within a step and raises KeyboardInterrupt, as any
Python call would: a run of a built-in method, a run of a Python controller, and a batch, which
leaves only whole results and runs the rest on a resume."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import camcov

# The longest run (100,000 steps), with a global step of 20,000 samples a camera every step:
# hours of work, so only Ctrl-C ends it in time.
LONG = {"sim.duration": 10000.0, "global.K": 20000, "global.T1": 0.1}


def press_ctrl_c_after(seconds):
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


def test_ctrl_c_stops_a_run_of_a_builtin_method(tiny):
    press_ctrl_c_after(0.5)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        camcov.run(tiny("tiny_dynamic"), method="paper", params=LONG)
    assert time.monotonic() - start < 5


def test_ctrl_c_stops_a_run_of_a_python_controller(tiny):
    cameras = len(camcov.load_scene(tiny("tiny_dynamic")).cameras)

    def slow_still(observation):  # a millisecond a step: 100 s for the longest run
        time.sleep(0.001)
        return np.zeros((cameras, 3))

    press_ctrl_c_after(0.5)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        camcov.simulate(tiny("tiny_dynamic"), slow_still, method="still", params=LONG)
    assert time.monotonic() - start < 5
    # And the next call runs normally.
    run = camcov.simulate(tiny("tiny_dynamic"), lambda o: np.zeros((cameras, 3)), method="still",
                          params={"sim.duration": 1.0})
    assert run.summary["averageCoverage"] >= 0.0


def test_ctrl_c_stops_a_batch_which_resumes_afterwards(tiny, tmp_path, capsys):
    out = tmp_path / "batch"
    options = dict(methods=["local"], seeds=200, out=str(out), params={"sim.duration": 60.0},
                   jobs=2, explorer="none", report=False, videos="none")
    press_ctrl_c_after(1.0)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        camcov.bench([tiny("tiny_dynamic")], **options)
    assert time.monotonic() - start < 10
    runs = out / "runs"
    files = list(runs.iterdir()) if runs.exists() else []
    assert not [p for p in files if p.name.endswith(".error.json")], "an interrupt is no failure"
    assert not [p for p in files if ".tmp-" in p.name], "only whole files"
    finished = len([p for p in files if p.suffix == ".json"])
    assert finished < 200
    capsys.readouterr()
    summary = camcov.bench([tiny("tiny_dynamic")], **options)
    assert summary["methods"][0]["runs"] == 200
    if finished:
        assert f"{finished} of 200 jobs already done" in capsys.readouterr().err
