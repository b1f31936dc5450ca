"""A camcov command ended by a signal (Ctrl-C's SIGINT, SIGTERM) leaves no temporary file behind:
a video's ".part" and an atomic write's ".tmp-PID" are removed, the whole files already written
stay, and the process ends by the signal it was sent, as the shell expects."""
import os
import pathlib
import signal
import subprocess
import time

import pytest


def camcov(*args):
    binary = os.environ.get("CAMCOV_BINARY")
    if not binary:
        pytest.fail("CAMCOV_BINARY is not set (ctest sets it)")
    return subprocess.Popen([binary, *map(str, args)], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)


def wait_for(condition, seconds=60):
    deadline = time.monotonic() + seconds
    while not condition():
        assert time.monotonic() < deadline, "the command never got there"
        time.sleep(0.01)


def temporaries(folder):
    return [p.name for p in pathlib.Path(folder).rglob("*") if ".tmp-" in p.name or
            p.name.endswith(".part")]


@pytest.mark.parametrize("sent", [signal.SIGINT, signal.SIGTERM])
def test_a_video_stopped_by_a_signal_leaves_no_part_file(tiny, tmp_path, sent):
    run = camcov("run", tiny("tiny_dynamic"), "--method", "local", "--duration", 600, "-o",
                 tmp_path / "runs")
    assert run.wait(timeout=120) == 0, run.stderr.read()
    video = tmp_path / "long.mp4"
    process = camcov("video", tmp_path / "runs" / "tiny_dynamic-local-seed1.json", "-o", video)
    part = tmp_path / "long.mp4.part"
    wait_for(lambda: part.exists() or process.poll() is not None)
    assert process.poll() is None, process.stderr.read()
    process.send_signal(sent)
    assert process.wait(timeout=10) == -sent
    assert temporaries(tmp_path) == []
    assert not video.exists()


def test_scenes_generated_until_ctrl_c_are_whole_and_nothing_else_is_left(tmp_path):
    out = tmp_path / "scenes"
    # Large scenes take a while to write: the signal lands among the writes, not after them.
    process = camcov("generate", "--family", "published_like", "--count", 100000, "-o", out)
    wait_for(lambda: len(list(out.glob("*.json"))) >= 20 or process.poll() is not None)
    assert process.poll() is None, process.stderr.read()
    process.send_signal(signal.SIGINT)
    assert process.wait(timeout=10) == -signal.SIGINT
    assert temporaries(out) == []
    written = sorted(out.iterdir())
    assert 20 <= len(written) < 100000
    check = camcov("validate", *written[:3])
    assert check.wait(timeout=60) == 0, check.stderr.read()
