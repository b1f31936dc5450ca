"""Scenes and parameters from Python: the CLI's validation, to the message."""
import json

import numpy as np
import pytest

import camcov
from conftest import TEST_DATA

BAD = sorted((TEST_DATA / "bad").glob("*.json"))


@pytest.mark.parametrize("file", BAD, ids=[f.stem for f in BAD])
def test_a_bad_scene_raises_input_error_with_the_clis_message(cli, file):
    with pytest.raises(camcov.InputError) as error:
        camcov.load_scene(str(file))
    result = cli("validate", file)
    assert result.returncode == 2
    assert f"error {file}: " in result.stdout + result.stderr
    # The CLI prints "error FILE: JSONPATH: problem"; Python's message is "FILE: JSONPATH: problem".
    assert str(error.value) in (result.stdout + result.stderr)


def test_input_error_is_a_value_error():
    assert issubclass(camcov.InputError, ValueError)


def test_a_scene_loads_with_its_cameras_and_the_world_at_t(tiny, cli):
    scene = camcov.load_scene(tiny("tiny_dynamic"))
    assert scene.name == "tiny_dynamic"
    assert scene.initial_poses.shape == (len(scene.cameras), 3)
    assert np.allclose(scene.half_fovs, np.radians(30))
    world = scene.world_at(1.5)
    assert world.time == 1.5
    state = json.loads(cli("state", tiny("tiny_dynamic"), "--time", "1.5").stdout)
    assert len(world.targets) == len(state["targets"])
    for ours, theirs in zip(world.targets, state["targets"]):
        assert np.array_equal(ours, np.array(theirs["polygon"]))
    for ours, theirs in zip(world.obstacles, state["obstacles"]):
        assert np.array_equal(ours, np.array(theirs["polygon"]))
    # One camera description: Python's dicts are what `camcov state` prints.
    assert scene.cameras == state["cameras"]
    assert scene.cameras[0]["cameraFoV"] == 30 and "sensingRange" not in scene.cameras[0]


def test_parse_scene_names_the_source_in_its_errors():
    with pytest.raises(camcov.InputError, match=r"^mine\.json: boundary: missing required key"):
        camcov.parse_scene('{"targets": []}', name="mine.json")


def test_parameters_take_dotted_keys_and_refuse_what_the_cli_refuses(cli):
    p = camcov.parameters({"global.K": 7, "safety.enabled": False})
    assert p["global"]["K"] == 7
    assert p["safety"]["enabled"] is False
    with pytest.raises(camcov.InputError) as error:
        camcov.parameters({"global.K": -1})
    result = cli("params", "--set", "global.K=-1")
    assert result.returncode == 2
    assert str(error.value) in result.stderr


def test_a_world_names_the_recorded_targets_present_by_their_index_in_the_scene():
    scene = camcov.load_scene(str(TEST_DATA / "scenes_tracks" / "comes_and_goes.json"))
    assert scene.world_at(0.2).target_ids == []
    assert scene.world_at(0.7).target_ids == [1]
    assert scene.world_at(1.5).target_ids == [0, 1]
    world = scene.world_at(2.8)
    assert world.target_ids == [0] and len(world.targets) == 1
    assert camcov.load_scene(str(TEST_DATA / "scenes" / "tiny_static.json")).world_at(0).target_ids == [0]
