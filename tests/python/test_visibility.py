"""Visibility and reward from Python agree with `camcov inspect`, and batches with single calls."""
import json

import numpy as np
import pytest

import camcov


def inspect(cli, scene_file, t):
    result = cli("inspect", scene_file, "--time", t, "--json")
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


@pytest.mark.parametrize("name, t", [("dynamic9", 3.0), ("static1", 0.0), ("dynamic1", 12.5)])
def test_segments_and_terms_agree_with_the_cli(cli, published, name, t):
    scene = camcov.load_scene(published(name))
    visibility = camcov.Visibility(scene.world_at(t), scene.half_fovs)
    segments = visibility.segments(scene.initial_poses)
    terms = visibility.terms(scene.initial_poses)
    reference = inspect(cli, published(name), t)
    for key in ("coverage", "utilization", "repulsion", "reward"):
        assert terms[key] == reference[key], key
    assert len(segments["a"]) == len(reference["segments"])
    for k, s in enumerate(reference["segments"]):
        assert segments["a"][k].tolist() == s["a"] and segments["b"][k].tolist() == s["b"]
        assert (segments["target"][k], segments["edge"][k]) == (s["target"], s["edge"])
        bits = [j for j in range(len(scene.initial_poses)) if (int(segments["visible_by"][k]) >> j) & 1]
        assert bits == s["visibleBy"]


def test_many_teams_in_one_call_are_each_team_on_its_own(published):
    scene = camcov.load_scene(published("dynamic9"))
    visibility = camcov.Visibility(scene.world_at(7.0), scene.half_fovs)
    rng = np.random.default_rng(3)
    teams = scene.initial_poses + rng.normal(0.0, 1.0, (20, *scene.initial_poses.shape))
    each = visibility.terms_each(teams)
    segments = visibility.segments_each(teams)
    for k, team in enumerate(teams):
        one = visibility.terms(team)
        assert each["coverage"][k] == one["coverage"] and each["reward"][k] == one["reward"]
        mine = segments["team"] == k
        alone = visibility.segments(team)
        assert np.array_equal(segments["a"][mine], alone["a"])
        assert np.array_equal(segments["visible_by"][mine], alone["visible_by"])
    singles = visibility.terms_each(teams[:, 0, :])  # (N, 3): one camera each, camera 0's θ
    assert singles["coverage"][4] == visibility.terms(teams[4, :1])["coverage"]


def test_a_team_of_more_than_64_cameras_names_each_one_that_sees(published):
    # 100 copies of one camera of dynamic9: each sees exactly what that camera sees alone, so
    # every segment is seen by all 100 or by none, as Python integers of 100 bits.
    scene = camcov.load_scene(published("dynamic9"))
    visibility = camcov.Visibility(scene.world_at(7.0), np.full(100, scene.half_fovs[0]))
    alone = camcov.Visibility(scene.world_at(7.0), scene.half_fovs[:1]).segments(
        scene.initial_poses[:1])
    seen = visibility.segments(np.repeat(scene.initial_poses[:1], 100, axis=0))
    assert seen["visible_by"].dtype == object
    everyone = (1 << 100) - 1
    assert [everyone if bits else 0 for bits in alone["visible_by"].tolist()] == \
        seen["visible_by"].tolist()
    assert any(bits == everyone for bits in seen["visible_by"].tolist())


def test_the_visibility_polygon_holds_its_point(published):
    scene = camcov.load_scene(published("static1"))
    polygon = camcov.Visibility(scene.world_at(0.0), scene.half_fovs).visibility_polygon(
        scene.initial_poses[0, :2])
    assert polygon.shape[1] == 2 and len(polygon) >= 3
    x, y = polygon[:, 0], polygon[:, 1]
    assert 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) > 0  # counter-clockwise


def test_bad_shapes_raise_value_errors(tiny):
    scene = camcov.load_scene(tiny("tiny_static"))
    visibility = camcov.Visibility(scene.world_at(0.0), scene.half_fovs)
    with pytest.raises(ValueError, match=r"\(M, 3\)"):
        visibility.terms(np.zeros((2, 2)))
    with pytest.raises(ValueError, match="fields of view"):
        visibility.terms(np.zeros((5, 3)))
    one = camcov.Visibility(scene.world_at(0.0), [0.5])
    with pytest.raises(ValueError, match="3 poses per team, but 1 fields of view"):
        one.terms(np.zeros((3, 3)))
    with pytest.raises(ValueError, match="one half-angle"):
        camcov.Visibility(scene.world_at(0.0), [])


def test_no_teams_give_no_terms_and_an_empty_team_sees_nothing(tiny):
    scene = camcov.load_scene(tiny("tiny_static"))
    visibility = camcov.Visibility(scene.world_at(0.0), scene.half_fovs)
    assert len(visibility.terms_each(np.zeros((0, 2, 3)))["coverage"]) == 0
    assert len(visibility.segments_each(np.zeros((0, 2, 3)))["a"]) == 0
    assert visibility.terms(np.zeros((0, 3)))["coverage"] == 0.0


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf, 2e9])
def test_numbers_no_scene_could_hold_raise_value_errors_naming_the_input(tiny, bad):
    scene = camcov.load_scene(tiny("tiny_static"))
    visibility = camcov.Visibility(scene.world_at(0.0), scene.half_fovs)
    for column in range(3):
        poses = np.array(scene.initial_poses)
        poses[0, column] = bad
        with pytest.raises(ValueError, match=r"poses: row 0 .*within"):
            visibility.terms(poses)
        with pytest.raises(ValueError, match=r"teams: row 0 .*within"):
            visibility.terms_each(poses[None])
    with pytest.raises(ValueError, match="point: entry 1"):
        visibility.visibility_polygon([0.0, bad])
    with pytest.raises(ValueError, match="world_at: t ="):
        scene.world_at(bad)
    with pytest.raises(ValueError, match="cameras: entry 0"):
        camcov.Visibility(scene.world_at(0.0), [bad])


@pytest.mark.parametrize("theta", [0.0, -0.1, np.pi, 4.0])
def test_a_half_angle_outside_zero_to_pi_or_too_many_cameras_raise_value_errors(tiny, theta):
    world = camcov.load_scene(tiny("tiny_static")).world_at(0.0)
    with pytest.raises(ValueError, match=r"half-angle must lie in \(0, π\)"):
        camcov.Visibility(world, [0.5, theta])
    with pytest.raises(ValueError, match="129 cameras; at most 128"):
        camcov.Visibility(world, np.full(129, 0.5))


RANGED_SCENE = {
    "boundary": "POLYGON((-10 -10,10 -10,10 10,-10 10))",
    "targets": [{"shape": "POLYGON((3 -1,5 -1,5 1,3 1))", "path": "POINT(0 0)"}],
    "obstacles": [],
    "cameraFoV": 60,
    "cameras": [{"pos": "POINT(0 0)", "angle": 0, "maxVelocity": 1, "maxAngularVelocity": 1,
                 "sensingRange": 9.25 ** 0.5}],
}


def test_a_scene_brings_its_cameras_sensing_ranges(tmp_path, cli):
    """r = √9.25 reaches |y| ≤ 0.5 of the near edge x = 3: 1 m of the 8 m perimeter."""
    path = tmp_path / "ranged.json"
    path.write_text(json.dumps(RANGED_SCENE))
    scene = camcov.load_scene(str(path))
    assert scene.cameras[0]["sensingRange"] == 9.25 ** 0.5
    world = scene.world_at(0.0)
    terms = camcov.Visibility(world, scene).terms(scene.initial_poses)
    assert terms["coverage"] == pytest.approx(1.0 / 8.0, abs=1e-12)
    assert terms["coverage"] == inspect(cli, str(path), 0.0)["coverage"]
    by_hand = camcov.Visibility(world, scene.half_fovs, sensing_ranges=[9.25 ** 0.5])
    assert by_hand.terms(scene.initial_poses)["coverage"] == terms["coverage"]
    endless = camcov.Visibility(world, scene.half_fovs, sensing_ranges=[float("inf")])
    unlimited = camcov.Visibility(world, scene.half_fovs).terms(scene.initial_poses)
    assert unlimited["coverage"] == pytest.approx(2.0 / 8.0, abs=1e-12)
    assert endless.terms(scene.initial_poses) == unlimited


def test_bad_sensing_ranges_raise_value_errors(tiny):
    scene = camcov.load_scene(tiny("tiny_static"))
    world = scene.world_at(0.0)
    assert all("sensingRange" not in c for c in scene.cameras)
    for bad in (-1.0, 0.0, float("nan")):
        with pytest.raises(ValueError, match="sensing_ranges: camera 0"):
            camcov.Visibility(world, [0.5], sensing_ranges=[bad])
    with pytest.raises(ValueError, match="expected 1 values"):
        camcov.Visibility(world, [0.5], sensing_ranges=[1.0, 2.0])
    with pytest.raises(ValueError, match="bring their own"):
        camcov.Visibility(world, scene, sensing_ranges=[1.0])


def test_hand_made_lenses_take_every_further_sensing_key_of_the_camera_table(tiny):
    world = camcov.load_scene(tiny("tiny_static")).world_at(0.0)
    pictured = camcov.Visibility(world, [0.5], image_widths=[640]).terms([[0.0, 0.0, 0.0]])
    assert pictured == camcov.Visibility(world, [0.5], image_widths=[0]).terms([[0.0, 0.0, 0.0]])
    with pytest.raises(ValueError, match="image_widths: camera 0: imageWidth must be a whole"):
        camcov.Visibility(world, [0.5], image_widths=[640.5])
    with pytest.raises(TypeError, match="a lens takes sensing_ranges, image_widths"):
        camcov.Visibility(world, [0.5], min_ranges=[1.0])
