"""camcov.env: the Gymnasium and PettingZoo environments, checked by the ecosystem's own checkers
(Gymnasium's check_env, PettingZoo's parallel_api_test and parallel_seed_test), against
`camcov run` (an episode driven by a method's policy is that method's run, to the bit), against
`camcov render` (the frames) and against the scene itself (the observation layout).

Gymnasium and PettingZoo are not Debian packages: their sources are in ../shared/vendor/python
(or CAMCOV_VENDOR_PYTHON), put on sys.path here, for tests only.
"""
import math
import os
import pathlib
import sys
import warnings

import numpy as np
import pytest

import camcov

REPO = pathlib.Path(__file__).resolve().parents[2]
VENDOR = pathlib.Path(os.environ.get("CAMCOV_VENDOR_PYTHON",
                                     REPO.parent / "shared" / "vendor" / "python"))
if not (VENDOR / "gymnasium").is_dir():
    pytest.fail(f"Gymnasium and PettingZoo's sources are not in {VENDOR} "
                "(set CAMCOV_VENDOR_PYTHON)", pytrace=False)
sys.path.insert(0, str(VENDOR))

import camcov.env as E  # noqa: E402
import gymnasium  # noqa: E402
from gymnasium.utils.env_checker import check_env  # noqa: E402
from pettingzoo.test import parallel_api_test, parallel_seed_test  # noqa: E402

SHORT = {"sim.duration": 2.0}  # 20 steps: enough for the checkers, quick


@pytest.fixture(scope="module")
def scenes(published):
    """Three published scenes (moving, still, one camera chasing a fast target) and a family."""
    return {"dynamic9": published("dynamic9"), "static14": published("static14"),
            "dynamic1": published("dynamic1"), "u_rooms": E.family("u_rooms", "tune", 3)}


def strictly(check, *args, **kwargs):
    """Runs a checker with every warning an error: camcov's environments give it none."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return check(*args, **kwargs)


@pytest.fixture(scope="module")
def recorded(cli, tmp_path_factory):
    """A recorded crowd whose people come and go: scenes/real/eth_univ.json if made, else
    made from ../shared/tracks as scripts/make_real_scenes.sh makes it."""
    made = REPO / "scenes" / "real" / "eth_univ.json"
    if made.is_file():
        return str(made)
    tracks = REPO.parent / "shared" / "tracks" / "pedestrians" / "eth_univ"
    if not tracks.is_dir():
        pytest.skip(f"no recorded tracks at {tracks}")
    out = tmp_path_factory.mktemp("real") / "eth_univ.json"
    result = cli("import", "ethucy", tracks, "--fps", 15, "--busiest", 60, "--cameras", 6,
                 "--camera-speed", 1.5, "--camera-turn", 1, "--fov", 30, "-o", out)
    assert result.returncode == 0, result.stderr
    return str(out)


COMES_AND_GOES = str(REPO / "tests" / "data" / "scenes_tracks" / "comes_and_goes.json")
CROWD = str(REPO / "scenes" / "crowd_large_room.json")  # 8 cameras of three speed limits


CHECKED = ["dynamic9", "static14", "dynamic1", "u_rooms", "comes_and_goes"]


def scene_of(scenes, name):
    return COMES_AND_GOES if name == "comes_and_goes" else scenes[name]


@pytest.mark.parametrize("name", CHECKED)
@pytest.mark.parametrize("options", [{}, {"action_units": "physical", "targets": 2}])
def test_gymnasiums_checker_passes_without_a_warning(scenes, name, options):
    env = gymnasium.make("camcov/Coverage-v0", scene=scene_of(scenes, name), params=SHORT,
                         **options)
    strictly(check_env, env.unwrapped, skip_render_check=False)


def test_gymnasiums_checker_passes_with_images_and_rendering(scenes):
    env = gymnasium.make("camcov/Coverage-v0", scene=scenes["dynamic9"], params=SHORT,
                         observation="image", image_size=(64, 48), render_mode="rgb_array",
                         render_size=(160, 120))
    strictly(check_env, env.unwrapped, skip_render_check=False)
    observation, _ = env.reset(seed=1)
    assert observation.shape == (48, 64, 3) and observation.dtype == np.uint8
    assert env.render().shape == (120, 160, 3)


@pytest.mark.parametrize("name", CHECKED)
@pytest.mark.parametrize("view,agent_reward,params", [
    ("team", "team", SHORT), ("own", "own", SHORT),
    ("known", "own", {**SHORT, "knowledge.limited": True, "comms.range": 10.0})])
def test_pettingzoos_checkers_pass_without_a_warning(scenes, name, view, agent_reward, params):
    def make():
        return E.make("camcov/CoverageParallel-v0", scene=scene_of(scenes, name), params=params,
                      view=view, agent_reward=agent_reward)

    strictly(parallel_api_test, make(), num_cycles=100)
    strictly(parallel_seed_test, make)


def test_gymnasium_make_and_make_vec_build_the_registered_environments(scenes):
    env = gymnasium.make("camcov/Coverage-v0", scene=scenes["dynamic9"], params=SHORT)
    assert isinstance(env.unwrapped, E.CoverageEnv) and env.spec.id == "camcov/Coverage-v0"
    threaded = gymnasium.make_vec("camcov/Coverage-v0", num_envs=3, scene=scenes["dynamic9"],
                                  params=SHORT)
    assert isinstance(threaded, E.VectorCoverageEnv) and threaded.num_envs == 3
    sync = gymnasium.make_vec("camcov/Coverage-v0", num_envs=3, vectorization_mode="sync",
                              scene=scenes["dynamic9"], params=SHORT)
    # The threaded form steps as Gymnasium's own vectorization of the single environment.
    first, _ = threaded.reset(seed=4)
    second, _ = sync.reset(seed=4)
    assert np.array_equal(first, second)
    actions = np.random.default_rng(1).uniform(-1, 1, threaded.action_space.shape)
    a, b = threaded.step(actions), sync.step(actions)
    for x, y in zip(a[:4], b[:4]):
        assert np.array_equal(x, y)
    assert set(a[4]) == set(b[4])
    # A config names the module to import: nothing needs importing camcov.env first.
    prefixed = gymnasium.make("camcov.env:camcov/Coverage-v0", scene=scenes["dynamic9"])
    assert prefixed.spec.id == "camcov/Coverage-v0"
    parallel = E.make("camcov/CoverageParallel-v0", scene=scenes["dynamic9"], params=SHORT)
    assert isinstance(parallel, E.CoverageParallelEnv)
    with pytest.raises(ValueError, match="id: expected one of camcov/Coverage-v0"):
        E.make("camcov/Cover-v0", scene=scenes["dynamic9"])


def test_a_normalized_action_of_one_moves_each_camera_at_its_own_limit():
    scene = camcov.load_scene(CROWD)
    dt = camcov.parameters()["sim"]["dt"]
    env = E.CoverageEnv(scene)
    assert env.action_space.dtype == np.float32
    assert np.all(env.action_space.low == -1) and np.all(env.action_space.high == 1)
    env.reset(seed=0)
    before = env.episodes.episode.cameras.copy()
    action = np.tile(np.float32([1, 0, -1]), (len(scene.cameras), 1))  # full speed along x
    env.step(action)
    after = env.episodes.episode.cameras
    for j, camera in enumerate(scene.cameras):
        assert after[j, 0] - before[j, 0] == pytest.approx(camera["maxVelocity"] * dt, rel=1e-9)
        assert after[j, 1] == pytest.approx(before[j, 1], abs=1e-12)
        turned = math.remainder(after[j, 2] - before[j, 2], 2 * math.pi)
        assert turned == pytest.approx(-camera["maxAngularVelocity"] * dt, rel=1e-9)
    # In physical units the same motion is the limits themselves, in m/s and rad/s.
    physical = E.CoverageEnv(scene, action_units="physical")
    physical.reset(seed=0)
    physical.step(np.array([[c["maxVelocity"], 0, -c["maxAngularVelocity"]]
                            for c in scene.cameras]))
    assert np.array_equal(physical.episodes.episode.cameras, after)
    assert physical.action_space.dtype == np.float64
    assert np.all(physical.action_space.high[:, 0] == [c["maxVelocity"] for c in scene.cameras])


def observations_of(env, steps, rng):
    """The observations of an episode of `steps` random steps (a dict per step for a parallel
    environment)."""
    if hasattr(env, "possible_agents"):
        observation, _ = env.reset(seed=1)
        seen = [observation]
        for _ in range(steps):
            if not env.agents:
                break
            observation = env.step({a: rng.uniform(-1, 1, 3) for a in env.agents})[0]
            seen.append(observation)
        return seen
    observation, _ = env.reset(seed=1)
    seen = [observation]
    for _ in range(steps):
        observation, _, _, truncated, _ = env.step(rng.uniform(-1, 1, env.action_space.shape))
        seen.append(observation)
        if truncated:
            break
    return seen


def test_observations_stay_within_their_declared_bounds(scenes, recorded):
    rng = np.random.default_rng(2)
    cases = [(scenes["dynamic9"], {}), (CROWD, {}), (COMES_AND_GOES, {}),
             (recorded, {"targets": 8}), (recorded, {})]
    for scene, options in cases:
        env = E.CoverageEnv(scene, params={"sim.duration": 20.0}, **options)
        for observation in observations_of(env, 200, rng):
            assert env.observation_space.contains(observation), scene
        for view in ("team", "own"):
            parallel = E.CoverageParallelEnv(scene, params={"sim.duration": 5.0}, view=view,
                                             **options)
            for observations in observations_of(parallel, 50, rng):
                for agent, observation in observations.items():
                    assert parallel.observation_space(agent).contains(observation), scene


def test_the_nearest_targets_keep_a_crowds_observation_one_size(recorded):
    env = E.CoverageEnv(recorded, targets=8)
    cameras, targets, obstacles, vertices = env.episodes.sizes
    assert targets == 8
    assert env.observation_space.shape == (4 + 10 * cameras + (5 + 2 * vertices) * 8 +
                                           (2 + 2 * vertices) * obstacles,)
    everyone = E.CoverageEnv(recorded).observation_space.shape[0]
    assert env.observation_space.shape[0] * 5 < everyone  # a slot for each of 70 people
    scene = camcov.load_scene(recorded)
    first = 4 + 10 * cameras
    present, filled = set(), set()
    observation, _ = env.reset(seed=0)
    for _ in range(env.episodes.episode.steps):
        assert observation.shape == env.observation_space.shape
        world = scene.world_at(env.episodes.episode.time)
        present.add(len(world.targets))
        flags = observation[first:first + 8 * (5 + 2 * vertices):5 + 2 * vertices]
        filled.add(int(flags.sum()))
        assert flags.sum() == min(8, len(world.targets))  # the slots fill first to last
        assert np.all(np.diff(flags) <= 0)
        observation, _, _, truncated, _ = env.step(np.zeros(env.action_space.shape))
        if truncated:
            break
    assert len(present) > 5  # people came and went, the size stayed


def test_agent_ids_tell_agents_apart_in_the_team_view(scenes):
    env = E.CoverageParallelEnv(scenes["dynamic9"], params=SHORT)
    observations, _ = env.reset(seed=0)
    team = env.state()
    for j, agent in enumerate(env.agents):
        observation = observations[agent]
        assert np.array_equal(observation[:len(team)], team)
        assert np.array_equal(observation[len(team):], np.eye(len(env.possible_agents))[j])
    assert len({observations[a].tobytes() for a in env.agents}) == len(env.agents)
    own = E.CoverageParallelEnv(scenes["dynamic9"], params=SHORT, view="own")
    observations, _ = own.reset(seed=0)
    poses = own.episodes.episode.cameras
    for j, agent in enumerate(own.agents):  # its own slot first, then every teammate
        camera = observations[agent][4:4 + 10 * len(poses)].reshape(len(poses), 10)
        assert camera[:, 0].sum() == len(poses)
        order = [j] + [k for k in range(len(poses)) if k != j]
        assert camera[:, 3] == pytest.approx(np.cos(poses[order, 2]), abs=1e-6)


def test_every_form_gives_the_same_info_keys(scenes):
    keys = set(E.Episodes.INFO_KEYS)
    final = keys | set(E.Episodes.FINAL_INFO_KEYS)
    single = E.CoverageEnv(scenes["dynamic9"], params=SHORT)
    _, info = single.reset(seed=0)
    assert set(info) == keys
    truncated = False
    while not truncated:
        _, _, _, truncated, info = single.step(np.zeros(single.action_space.shape))
        assert set(info) == (final if truncated else keys)
    parallel = E.CoverageParallelEnv(scenes["dynamic9"], params=SHORT)
    _, infos = parallel.reset(seed=0)
    assert all(set(i) == keys for i in infos.values())
    while parallel.agents:
        *_, infos = parallel.step({a: np.zeros(3, np.float32) for a in parallel.agents})
        assert all(set(i) == (keys if parallel.agents else final) for i in infos.values())
    vector = E.VectorCoverageEnv(scenes["dynamic9"], 2, params=SHORT)
    _, infos = vector.reset(seed=0)
    assert set(infos) == keys | {"_" + k for k in keys}
    truncated = np.zeros(2, bool)
    while not truncated.all():
        *_, truncated, infos = vector.step(np.zeros(vector.action_space.shape))
    assert set(infos) == final | {"_" + k for k in final}
    assert infos["average_coverage"][0] == infos["summary"][0]["averageCoverage"]


def test_one_policy_runs_on_scenes_of_different_sizes(scenes):
    """A linear policy, its weights fixed once, drives a five-camera scene without obstacles
    and an eight-camera one with three: the nearest targets and the padding give both one
    observation shape, normalized actions one meaning."""
    options = dict(targets=6, pad_to={"cameras": 8, "obstacles": 4, "vertices": 12},
                   params={"sim.duration": 3.0})
    weights = np.random.default_rng(3).normal(size=(3, 4 + 10 * 8 + 29 * 6 + 26 * 4)) * 0.05

    def policy(observation):  # one agent's egocentric view -> its command
        return np.tanh(weights @ observation).astype(np.float32)

    for scene in (scenes["dynamic9"], CROWD):
        env = E.CoverageParallelEnv(scene, view="own", **options)
        observations, _ = env.reset(seed=0)
        steps = 0
        while env.agents:
            observations, *_ = env.step({a: policy(observations[a]) for a in env.agents})
            steps += 1
        assert steps == 30
        team = E.CoverageEnv(scene, **options)  # the team's action: one row per camera slot
        observation, _ = team.reset(seed=0)
        team.step(np.stack([policy(observation)] * 8))


@pytest.mark.parametrize("scene,method", [("dynamic9", "paper"), ("dynamic1", "camcov"),
                                          ("static14", "local")])
def test_a_method_as_a_policy_reproduces_camcov_run_bit_for_bit(scenes, scene, method):
    env = E.CoverageEnv(scenes[scene])
    _, info = env.reset(seed=5, options={"seed": 3})  # the run seed: 3
    assert info["seed"] == 3
    drive = E.policy(method, env)
    coverage, summary = [info["coverage"]], None
    while summary is None:
        _, _, terminated, truncated, info = env.step(drive(None))
        assert not terminated
        coverage.append(info["coverage"])
        summary = info.get("summary") if truncated else None
    run = camcov.run(scenes[scene], method, 3)
    assert np.array_equal(np.array(coverage), run.coverage)
    assert summary["averageCoverage"] == run.summary["averageCoverage"]


def test_a_policy_makes_its_controller_anew_for_each_episode(scenes):
    env = E.CoverageEnv(scenes["dynamic9"], params={"sim.duration": 1.0})
    drive = E.policy("paper", env)
    first = []
    for _ in range(2):
        env.reset(options={"seed": 1})
        actions = [drive(None)]
        truncated = False
        while not truncated:
            _, _, _, truncated, _ = env.step(actions[-1])
            if not truncated:
                actions.append(drive(None))
        first.append(np.array(actions))
    assert np.array_equal(first[0], first[1])  # the same seed, a fresh controller: the same run


def test_the_vector_form_steps_on_threads_as_one_environment_would(scenes):
    family = scenes["u_rooms"]
    vector = E.VectorCoverageEnv(family, 3, threads=2, params=SHORT)
    single = [E.CoverageEnv(family, params=SHORT) for _ in range(3)]
    observations, _ = vector.reset(seed=10)
    for i, env in enumerate(single):
        alone, _ = env.reset(seed=10 + i)
        assert np.array_equal(observations[i], alone)
    rng = np.random.default_rng(0)
    ended = 0
    for _ in range(25):  # past the end: the next step starts a new episode
        actions = rng.uniform(-1, 1, vector.action_space.shape)
        observations, rewards, terminated, truncated, infos = vector.step(actions)
        assert not terminated.any()
        for i, env in enumerate(single):
            if env.episodes.episode.finished:  # next-step autoreset
                env.reset()
                continue
            alone, reward, _, done, info = env.step(actions[i])
            assert np.array_equal(observations[i], alone) and rewards[i] == reward
            assert truncated[i] == done
            if done:
                ended += 1
                assert infos["_average_coverage"][i]
                assert infos["average_coverage"][i] == info["summary"]["averageCoverage"]
    assert ended == 3


def test_the_vector_form_takes_a_methods_policy(scenes):
    vector = E.VectorCoverageEnv(scenes["dynamic9"], 2, params={"sim.duration": 3.0})
    vector.reset(seed=1, options={"seed": 7})
    drive = E.policy("paper", vector)
    coverage = []
    for _ in range(30):
        _, _, _, truncated, infos = vector.step(drive(None))
        coverage.append(infos["coverage"])
    assert truncated.all()
    run = camcov.run(scenes["dynamic9"], "paper", 7, params={"sim.duration": 3.0})
    for i in range(2):
        assert np.array_equal(np.array([c[i] for c in coverage]), run.coverage[1:])


def test_the_observation_is_the_documented_layout(tiny):
    scene = camcov.load_scene(tiny("tiny_dynamic"))
    env = E.CoverageEnv(scene)
    observation, info = env.reset(seed=0)
    cameras, targets, obstacles, vertices = env.episodes.sizes
    assert env.observation_space.shape == (4 + 10 * cameras + (5 + 2 * vertices) * targets +
                                           (2 + 2 * vertices) * obstacles,)
    world = scene.world_at(0.0)
    box_min, box_max = world.boundary.min(axis=0), world.boundary.max(axis=0)
    centre, half = (box_min + box_max) / 2, (box_max - box_min).max() / 2
    assert observation[0] == 0.0 and observation[1] == np.float32(info["coverage"])
    camera = observation[4:14]
    pose = scene.initial_poses[0]
    assert camera[0] == 1
    assert camera[1:3] == pytest.approx((pose[:2] - centre) / half, abs=1e-6)
    assert camera[3:5] == pytest.approx([math.cos(pose[2]), math.sin(pose[2])], abs=1e-6)
    assert camera[5] == pytest.approx(scene.cameras[0]["maxVelocity"] / half)
    assert camera[7] == pytest.approx(scene.half_fovs[0])
    # The names of the columns the lines above read, by the camera table's observed keys.
    assert camcov.camera_columns() == ["present", "x", "y", "cos yaw", "sin yaw", "maxVelocity",
                                       "maxAngularVelocity", "cameraFoV", "sensingRange",
                                       "coverage"]
    target = observation[4 + 10 * cameras:][:5 + 2 * vertices]
    ring = world.targets[0]
    assert target[0] == 1 and target[4] == pytest.approx(len(ring) / vertices)
    assert target[2:4] == pytest.approx((ring.mean(axis=0) - centre) / half, abs=1e-6)
    assert target[5:5 + 2 * len(ring)] == pytest.approx(((ring - centre) / half).ravel(),
                                                        abs=1e-6)


def test_rendering_draws_the_frame_camcov_render_draws(tiny, cli, tmp_path):
    pil = pytest.importorskip("PIL.Image")
    env = E.CoverageEnv(tiny("tiny_dynamic"), render_mode="rgb_array", render_size=(200, 150))
    env.reset(seed=0)
    png = tmp_path / "frame.png"
    result = cli("render", tiny("tiny_dynamic"), "--time", "0", "--width", "200", "--height",
                 "150", "-o", png)
    assert result.returncode == 0, result.stderr
    drawn = np.asarray(pil.open(png).convert("RGB"))
    # camcov render's caption says where the cameras are; the environment's frame, with the
    # same words, is the same picture.
    frame = env.episodes.episode.frame(200, 150, subtitle="cameras at their initial poses")
    assert np.array_equal(frame, drawn)
    assert env.render().shape == drawn.shape and not np.array_equal(env.render(), drawn)


def test_bad_input_raises_naming_the_argument(scenes):
    env = E.CoverageEnv(scenes["dynamic9"], params=SHORT)
    with pytest.raises(RuntimeError, match="reset"):
        env.step(np.zeros(env.action_space.shape))
    env.reset(seed=0)
    with pytest.raises(ValueError, match=r"action: expected shape \(5, 3\)"):
        env.step(np.zeros((4, 3)))
    bad = np.zeros(env.action_space.shape)
    bad[2, 1] = math.nan
    with pytest.raises(ValueError, match="action: camera 2's command is not finite"):
        env.step(bad)
    bad[2, 1] = math.inf
    with pytest.raises(ValueError, match="not finite"):
        env.step(bad)
    with pytest.raises(TypeError, match="colour"):
        E.CoverageEnv(scenes["dynamic9"], colour="red")
    with pytest.raises(ValueError, match="reward: expected one of"):
        E.CoverageEnv(scenes["dynamic9"], reward="fun")
    with pytest.raises(ValueError, match="observation: expected"):
        E.CoverageEnv(scenes["dynamic9"], observation="sound")
    with pytest.raises(camcov.InputError, match="sim.duration"):
        E.CoverageEnv(scenes["dynamic9"], params={"sim.duration": math.nan})
    with pytest.raises(ValueError, match="the list is empty"):
        E.CoverageEnv([])
    with pytest.raises(ValueError, match="action_units: expected one of"):
        E.CoverageEnv(scenes["dynamic9"], action_units="km/h")
    for targets in (0, 2.5, "all"):
        with pytest.raises(ValueError, match="targets: expected None or a number"):
            E.CoverageEnv(scenes["dynamic9"], targets=targets)
    with pytest.raises(ValueError, match=r"pad_to\['cameras'\]: expected 5 \(what the scenes"):
        E.CoverageEnv(scenes["dynamic9"], pad_to={"cameras": 4})
    with pytest.raises(ValueError, match="pad_to: expected keys among"):
        E.CoverageEnv(scenes["dynamic9"], pad_to={"targets": 9})
    with pytest.raises(ValueError, match="family: no family 'x_rooms'"):
        E.family("x_rooms")
    with pytest.raises(ValueError, match="method: no method 'oracle'"):
        E.policy("oracle", env)
    with pytest.raises(ValueError, match="options\\['scene'\\]"):
        env.reset(options={"scene": 3})
    parallel = E.CoverageParallelEnv(scenes["dynamic9"], params=SHORT)
    parallel.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions\['camera_1'\]: expected shape \(3,\)"):
        parallel.step({"camera_1": [1.0, 2.0]})
    with pytest.raises(ValueError, match="no agents \\['camera_9'\\]"):
        parallel.step({"camera_9": [0.0, 0.0, 0.0]})
    vector = E.VectorCoverageEnv(scenes["dynamic9"], 2, params=SHORT)
    vector.reset(seed=0)
    with pytest.raises(ValueError, match=r"actions: expected shape \(2, 5, 3\)"):
        vector.step(np.zeros((5, 3)))
    nan = np.zeros(vector.action_space.shape)
    nan[1, 0, 0] = math.nan
    with pytest.raises(ValueError, match=r"actions\[1\]: camera 0's command is not finite"):
        vector.step(nan)
    # Sizes, threads and counts that would overflow or exhaust the machine are refused.
    episode = env.episodes.episode
    with pytest.raises(ValueError, match="sizes: 4611686018427387904 cameras, at most 128"):
        episode.observation((2**62, 1, 0, 4))
    with pytest.raises(ValueError, match="sizes: .* vertices, at most 1000000"):
        episode.observation((5, 6, 0, 2**61))
    for threads in (0, 10**6):
        with pytest.raises((ValueError, TypeError), match="threads"):
            camcov.EpisodeStepper(threads)
    with pytest.raises(ValueError, match="threads: expected a whole number from 1 to 256"):
        E.VectorCoverageEnv(scenes["dynamic9"], 2, threads=1000)
    with pytest.raises(ValueError, match="seed: expected one seed or 2, got 3"):
        vector.reset(seed=[1, 2, 3])
    with pytest.raises(ValueError, match="num_envs: expected a whole number from 1 to 65536"):
        E.VectorCoverageEnv(scenes["dynamic9"], 10**7)


def test_the_core_needs_neither_gymnasium_nor_pettingzoo(tmp_path):
    """camcov and camcov.env import without them; only the environments' classes need them."""
    import subprocess
    code = ("import sys; sys.modules['gymnasium'] = None; sys.modules['pettingzoo'] = None\n"
            "import camcov, camcov.env\n"
            "assert callable(camcov.env.policy) and callable(camcov.env.family)\n"
            "try:\n    camcov.env.CoverageEnv\nexcept ImportError:\n    print('lazy')\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            cwd=tmp_path, env={**os.environ, "PYTHONPATH": os.pathsep.join(
                                p for p in sys.path if p and "vendor" not in p)})
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == "lazy"


def test_every_public_name_of_the_environments_has_a_docstring():
    import importlib

    from test_docstrings import undocumented
    for name in ("camcov.env", "camcov._gym_env", "camcov._parallel_env", "camcov._vector_env"):
        module = importlib.import_module(name)
        ours = [where for where in undocumented(module)
                if getattr(getattr(module, where.split(".")[2]), "__module__", "").startswith(
                    "camcov")]
        assert ours == [], name


def test_the_examples_run_and_training_raises_coverage(published, tmp_path):
    import subprocess
    examples = REPO / "examples"
    environment = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in sys.path if p)}
    run = subprocess.run([sys.executable, examples / "env_policies.py", published("dynamic9")],
                         capture_output=True, text=True, cwd=tmp_path, env=environment)
    assert run.returncode == 0, run.stdout + run.stderr
    assert "(the same)" in run.stdout
    sys.path.insert(0, str(examples))
    try:
        import env_cross_entropy
    finally:
        sys.path.remove(str(examples))
    env = E.CoverageEnv(env_cross_entropy.TINY, params={"sim.duration": 10.0})
    history = env_cross_entropy.train(env, iterations=5, population=20, seed=1,
                                      report=lambda line: None)
    assert history[0] == 0.0  # the camera starts facing away
    assert history[-1] > 0.1, history


def test_a_scenes_own_duration_is_the_episodes_unless_the_parameters_say(tiny):
    import json
    with open(tiny("tiny_dynamic")) as f:
        text = json.load(f)
    text["duration"] = 1.2  # as `camcov import` writes a recording's window
    scene = camcov.parse_scene(json.dumps(text), name="timed.json")
    for params, steps in ((None, 12), ({"sim.duration": 0.5}, 5)):
        env = E.CoverageEnv(scene, params=params)
        env.reset(seed=0)
        taken, truncated = 0, False
        while not truncated:
            _, _, _, truncated, _ = env.step(np.zeros(env.action_space.shape))
            taken += 1
        assert taken == steps


@pytest.mark.parametrize("weighted", [True, False])
def test_the_coverage_reward_is_the_one_the_reward_takes_on_a_weighted_scene(weighted):
    """On a scene with importance weights, reward="coverage" is the weighted coverage, or the
    plain one with reward.weighted off, in the single and the vector form alike."""
    scene = str(REPO / "scenes" / "weighted_stage_and_walkers.json")
    params = {"sim.duration": 2.0, "reward.weighted": weighted}
    single = E.CoverageEnv(scene, params=params, reward="coverage")
    vector = E.VectorCoverageEnv(scene, 1, params=params, reward="coverage")
    single.reset(seed=3)
    vector.reset(seed=3)
    rng = np.random.default_rng(1)
    differ = False
    for _ in range(10):
        actions = rng.uniform(-1, 1, vector.action_space.shape)
        _, reward, _, _, info = single.step(actions[0])
        _, rewards, _, _, _ = vector.step(actions)
        key = "weightedCoverage" if weighted else "coverage"
        assert reward == info[key] and rewards[0] == reward
        differ |= info["weightedCoverage"] != info["coverage"]
    assert differ, "the scene's weights changed nothing"


def test_under_limited_knowledge_the_agents_observe_the_known_world_and_are_rewarded_by_the_true(
        published):
    scene = published("dynamic5")
    limited = {**SHORT, "knowledge.limited": True}
    full_env = E.CoverageEnv(scene, params=SHORT)
    limited_env = E.CoverageEnv(scene, params=limited)
    full_observation, _ = full_env.reset(seed=1)
    limited_observation, _ = limited_env.reset(seed=1)
    assert not np.array_equal(full_observation, limited_observation)  # a target not yet seen
    action = np.zeros(full_env.action_space.shape, dtype=full_env.action_space.dtype)
    for _ in range(5):
        _, full_reward, *_ = full_env.step(action)
        _, limited_reward, *_ = limited_env.step(action)
        assert limited_reward == full_reward
    full_agents = E.CoverageParallelEnv(scene, params=SHORT, agent_reward="own")
    limited_agents = E.CoverageParallelEnv(scene, params=limited, agent_reward="own")
    full_agents.reset(seed=1)
    limited_agents.reset(seed=1)
    still = {agent: np.zeros(full_agents.action_space(agent).shape, dtype=np.float32)
             for agent in full_agents.agents}
    _, full_rewards, *_ = full_agents.step(still)
    _, limited_rewards, *_ = limited_agents.step(still)
    assert limited_rewards == full_rewards


def test_a_known_view_is_what_its_camera_knows(published):
    """view="known": with full knowledge the team's observation with the agent's slot first;
    under limited knowledge with nobody heard (comms.range 0 on dynamic5, whose cameras stand
    apart), a target's slot is present only for the agent whose camera has seen it, which the
    true world's S (visibleBy) tells apart at the first instant."""
    scene = published("dynamic5")
    full = E.CoverageParallelEnv(scene, params=SHORT, view="known")
    observations, _ = full.reset(seed=1)
    team = full.state()
    cameras = full.episodes.cameras()
    for j, agent in enumerate(full.agents):
        order = [j] + [k for k in range(cameras) if k != j]
        slots = team[4:4 + 10 * cameras].reshape(cameras, 10)[order].ravel()
        expected = np.concatenate([team[:4], slots, team[4 + 10 * cameras:]])
        assert np.array_equal(observations[agent], expected)

    limited = E.CoverageParallelEnv(
        scene, params={**SHORT, "knowledge.limited": True, "comms.range": 0.0}, view="known")
    observations, _ = limited.reset(seed=1)
    loaded = camcov.load_scene(scene)
    truth = camcov.Visibility(loaded.world_at(0.0), loaded).segments(
        limited.episodes.episode.cameras)
    sizes = limited.episodes.sizes
    first_target = 4 + 10 * sizes[0]
    per_target = 5 + 2 * sizes[3]
    knows_some = False
    for j, agent in enumerate(limited.agents):
        saw = {int(t) for t, by in zip(truth["target"], truth["visible_by"]) if int(by) >> j & 1}
        present = {i for i in range(sizes[1])
                   if observations[agent][first_target + i * per_target] == 1.0}
        assert present == saw, f"camera {j}"
        knows_some |= bool(saw)
    assert knows_some, "nobody sees a target at t = 0: the check would be empty"
