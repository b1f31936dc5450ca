"""Runs from Python: the CLI's bytes for the built-in methods, Python controllers whose files
every command takes, batches with both, and errors that say what went wrong."""
import json
import pathlib
import threading

import numpy as np
import pytest

import camcov
from nearest_unseen import NearestUnseen

SHORT = {"sim.duration": 3.0, "global.K": 30, "planner.T2": 0.05}


def cli_run(cli, scene_file, method, seed, out, duration):
    result = cli("run", scene_file, "--method", method, "--seed", seed, "--duration", duration,
                 "--set", "global.K=30", "--set", "planner.T2=0.05", "--out", out)
    assert result.returncode == 0, result.stderr
    return pathlib.Path(out)


@pytest.mark.parametrize("method", ["paper", "local", "camcov", "nearest-unseen"])
def test_a_run_is_the_clis_to_the_byte(cli, tiny, tmp_path, method):
    scene_file = tiny("tiny_dynamic")
    run = camcov.run(scene_file, method=method, seed=2, params=SHORT)
    ours = pathlib.Path(run.write(str(tmp_path / "python")))
    theirs = cli_run(cli, scene_file, method, 2, tmp_path / "cli", 3) / ours.name
    assert ours.read_bytes() == theirs.read_bytes()
    assert ours.with_suffix(".csv").read_bytes() == theirs.with_suffix(".csv").read_bytes()
    assert run.summary["averageCoverage"] == json.loads(theirs.read_text())["summary"]["averageCoverage"]


def test_the_python_twin_of_the_cpp_example_makes_the_same_run(published, tmp_path):
    scene_file = published("dynamic9")
    python = camcov.simulate(scene_file, NearestUnseen(camcov.load_scene(scene_file)),
                             method="nearest-unseen-py")
    cpp = camcov.run(scene_file, method="nearest-unseen")
    ours = json.loads(pathlib.Path(python.write(str(tmp_path))).read_text())
    theirs = json.loads(pathlib.Path(cpp.write(str(tmp_path))).read_text())
    assert ours.pop("method") == "nearest-unseen-py" and theirs.pop("method") == "nearest-unseen"
    assert ours == theirs
    assert np.array_equal(python.coverage, cpp.coverage)


def test_a_python_controllers_run_is_taken_by_video_and_report(cli, tiny, tmp_path):
    scene_file = tiny("tiny_static")
    scene = camcov.load_scene(scene_file)
    spin = np.tile([0.0, 0.0, 0.5], (len(scene.cameras), 1))
    run = camcov.simulate(scene_file, lambda observation: spin, method="spin", seed=1,
                          params={"sim.duration": 2.0})
    assert run.stem == "tiny_static-spin-seed1"
    written = run.write(str(tmp_path / "runs"))
    video = cli("video", written, "-o", tmp_path / "spin.mp4", "--width", "320")
    assert video.returncode == 0, video.stderr
    assert (tmp_path / "spin.mp4").stat().st_size > 0
    summary = camcov.bench([scene_file], methods=["local"], seeds=1, out=str(tmp_path / "batch"),
                           params={"sim.duration": 2.0}, controllers={"spin": lambda s, p, seed: (
                               lambda observation: spin)})
    assert {t["method"] for t in summary["totals"]} == {"spin"}
    assert (tmp_path / "batch" / "runs" / "tiny_static-spin-seed1.json").read_bytes() == \
        pathlib.Path(written).read_bytes()
    report = cli("report", tmp_path / "batch")
    assert report.returncode == 0, report.stderr
    assert 'data-method="spin"' in (tmp_path / "batch" / "report.html").read_text()


def test_bench_runs_python_and_cpp_methods_and_merge_takes_its_shards(cli, tiny, tmp_path):
    scenes = [tiny("tiny_static"), tiny("tiny_dynamic")]
    controllers = {"nearest-unseen-py": NearestUnseen}
    summary = camcov.bench(scenes, methods=["local", "nearest-unseen"], seeds=2,
                           out=str(tmp_path / "all"), params=SHORT, controllers=controllers,
                           jobs=2)
    assert summary["reference"] == "local"
    assert {t["method"] for t in summary["totals"]} == {"nearest-unseen", "nearest-unseen-py"}
    # The twins tie everywhere: same runs.
    runs = tmp_path / "all" / "runs"
    for scene in ("tiny_static", "tiny_dynamic"):
        a = json.loads((runs / f"{scene}-nearest-unseen-seed1.json").read_text())
        b = json.loads((runs / f"{scene}-nearest-unseen-py-seed1.json").read_text())
        assert a["summary"] == b["summary"]
    merged = cli("merge", tmp_path / "all", "--out", tmp_path / "merged", "--videos", "none")
    assert merged.returncode == 0, merged.stderr
    assert (tmp_path / "merged" / "summary.json").read_bytes() == \
        (tmp_path / "all" / "summary.json").read_bytes()


def test_a_failing_python_controller_fails_its_job_with_the_python_error(tiny, tmp_path):
    def broken(scene, params, seed):
        def control(observation):
            raise RuntimeError("my controller is broken")
        return control
    summary = camcov.bench([tiny("tiny_static")], methods=["local"], seeds=1,
                           out=str(tmp_path), params=SHORT, controllers={"broken": broken},
                           report=False)
    assert len(summary["failures"]) == 1
    assert "my controller is broken" in summary["failures"][0]["error"]
    with pytest.raises(RuntimeError, match="my controller is broken"):
        camcov.simulate(tiny("tiny_static"), broken(None, None, 1), method="broken", params=SHORT)


def test_bad_input_raises_the_clis_errors(tiny, tmp_path):
    with pytest.raises(camcov.InputError, match="unknown method 'nope'"):
        camcov.run(tiny("tiny_static"), method="nope")
    with pytest.raises(camcov.InputError, match="is a built-in method's"):
        camcov.simulate(tiny("tiny_static"), lambda o: None, method="paper")
    with pytest.raises(camcov.InputError, match="lowercase"):
        camcov.simulate(tiny("tiny_static"), lambda o: None, method="My Method")
    with pytest.raises(ValueError, match="velocities"):
        camcov.simulate(tiny("tiny_static"), lambda o: np.zeros((7, 3)), method="wrong",
                        params=SHORT)
    cameras = len(camcov.load_scene(tiny("tiny_static")).cameras)
    with pytest.raises(ValueError, match="not finite for camera 0 at t = 0"):
        camcov.simulate(tiny("tiny_static"), lambda o: np.full((cameras, 3), np.inf),
                        method="wrong", params=SHORT)
    with pytest.raises(ValueError, match="'kind' must be a str"):
        camcov.simulate(tiny("tiny_static"),
                        lambda o: (np.zeros((cameras, 3)), None, [{"kind": 5}]),
                        method="wrong", params=SHORT)


def test_a_limited_knowledge_run_is_the_clis_to_the_byte_and_counts_its_messages(
        cli, tiny, tmp_path):
    scene_file = tiny("tiny_static")  # two cameras
    limited = {**SHORT, "knowledge.limited": True, "comms.range": float("inf"),
               "comms.loss": 0.3}
    run = camcov.run(scene_file, method="paper", seed=2, params=limited)
    ours = pathlib.Path(run.write(str(tmp_path / "python")))
    result = cli("run", scene_file, "--method", "paper", "--seed", 2, "--duration", 3,
                 "--set", "global.K=30", "--set", "planner.T2=0.05",
                 "--set", "knowledge.limited=true", "--set", "comms.range=inf",
                 "--set", "comms.loss=0.3", "--out", tmp_path / "cli")
    assert result.returncode == 0, result.stderr
    assert ours.read_bytes() == (tmp_path / "cli" / ours.name).read_bytes()
    messages = run.summary["messages"]
    assert messages["sent"] == messages["delivered"] + messages["lost"]  # no latency
    assert 0 < messages["lost"] < messages["sent"]
    assert "messages" not in camcov.run(scene_file, method="paper", seed=2, params=SHORT).summary
    with pytest.raises(camcov.InputError, match="comms.loss"):
        camcov.run(scene_file, method="paper", params={"comms.loss": 2})


def test_a_controller_under_limited_knowledge_receives_what_each_camera_knows(tiny):
    """observation.own: per camera its own world and its teammates as last heard. With
    comms.range 0 nobody hears anybody, so every teammate entry stays None and each camera's
    world holds no more targets than the team's; with unlimited range every camera hears the
    other at once (no latency), with the pose it sent at that instant."""
    scene_file = tiny("tiny_static")  # two cameras
    seen = []

    def still(observation):
        seen.append((observation.time, observation.cameras.copy(), observation.own,
                     len(observation.world.targets)))
        return np.zeros((len(observation.cameras), 3))

    camcov.simulate(scene_file, still, method="still", seed=1,
                    params={**SHORT, "knowledge.limited": True, "comms.range": 0.0})
    for _, cameras, own, team_targets in seen:
        assert len(own) == len(cameras)
        for j, knowledge in enumerate(own):
            assert knowledge["teammates"] == [None] * len(cameras)
            assert len(knowledge["world"].targets) <= team_targets
    seen.clear()
    camcov.simulate(scene_file, still, method="still", seed=1,
                    params={**SHORT, "knowledge.limited": True, "comms.range": float("inf")})
    time, cameras, own, _ = seen[0]
    for j, knowledge in enumerate(own):
        for k, news in enumerate(knowledge["teammates"]):
            if k == j:
                assert news is None
            else:
                assert news["sent_at"] == time
                assert news["pose"] == pytest.approx(cameras[k])
    seen.clear()
    camcov.simulate(scene_file, still, method="still", seed=1, params=SHORT)
    assert all(own == [] for _, _, own, _ in seen), "full knowledge: nothing per camera"


def test_the_gil_is_let_go_while_cpp_runs(published):
    # While a run works in another thread, this thread keeps running Python: with the GIL
    # held for the whole run it could not count at all until the run returned.
    scene_file = published("dynamic9")
    started = threading.Event()

    def work():
        started.set()
        camcov.run(scene_file, method="paper", seed=1)

    thread = threading.Thread(target=work)
    thread.start()
    started.wait()
    counted = 0
    while thread.is_alive():
        counted += 1
    thread.join()
    assert counted > 1000


def test_the_example_script_writes_a_report_of_both_methods(published, tmp_path):
    import subprocess
    import sys
    from conftest import REPO
    out = tmp_path / "example"
    scenes = pathlib.Path(published("static1")).parent
    result = subprocess.run([sys.executable, str(REPO / "examples" / "python_bench.py"),
                             "--scenes", str(scenes), "--out", str(out), "--seeds", "2",
                             "--duration", "2"], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["reference"] == "paper"
    assert {c["scene"] for c in summary["comparisons"]} == {"static1", "dynamic1", "dynamic9"}
    assert {c["method"] for c in summary["comparisons"]} == {"nearest-unseen-py"}
    report = (out / "report.html").read_text()
    assert 'data-method="nearest-unseen-py"' in report and 'data-method="paper"' in report


def test_a_python_controllers_goals_and_events_are_kept_in_its_results(tiny, tmp_path):
    scene = camcov.load_scene(tiny("tiny_static"))
    m = len(scene.cameras)

    def control(observation):
        goals = np.full((m, 3), np.nan)
        goals[0] = (1.0, -5.0, 0.5)
        events = []
        if observation.time == 0.0:
            events.append({"kind": "plan", "camera": 0, "detail": "toward (1, -5)",
                           "reason": "start", "path": [[-6.0, -6.0, 0.0], [1.0, -5.0, 0.5]]})
        return np.zeros((m, 3)), goals, events

    run = json.loads(pathlib.Path(camcov.simulate(
        tiny("tiny_static"), control, method="planner-py", params={"sim.duration": 1.0}
    ).write(str(tmp_path))).read_text())
    event = run["events"][0]
    assert (event["kind"], event["camera"], event["reason"]) == ("plan", 0, "start")
    assert event["time"] == 0.0 and len(event["path"]) == 2
    with pytest.raises(ValueError, match="without 'kind'"):
        camcov.simulate(tiny("tiny_static"), lambda o: (np.zeros((m, 3)), None, [{}]),
                        method="bad-events", params={"sim.duration": 1.0})
