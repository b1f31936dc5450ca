"""Python code cannot crash the interpreter through camcov: every object that holds native
state either serves several Python threads at once (they take turns) or refuses a misuse with
a camcov exception naming it. One case of each kind of misuse, and threads hammering one
object of each class; the references are counts the test keeps itself (each step that returned
moves an episode on by exactly one instant).
"""
import os
import pathlib
import sys
import threading

import numpy as np
import pytest

import camcov

REPO = pathlib.Path(__file__).resolve().parents[2]
VENDOR = pathlib.Path(os.environ.get("CAMCOV_VENDOR_PYTHON",
                                     REPO.parent / "shared" / "vendor" / "python"))
SHORT = {"sim.duration": 3.0}  # 30 steps


@pytest.fixture(scope="module")
def dynamic():
    return camcov.load_scene(str(REPO / "tests" / "data" / "scenes" / "tiny_dynamic.json"))


@pytest.fixture(scope="module")
def static():
    return camcov.load_scene(str(REPO / "tests" / "data" / "scenes" / "tiny_static.json"))


@pytest.fixture(scope="module")
def envs():
    """camcov.env with Gymnasium and PettingZoo's sources (../shared/vendor/python)."""
    if not (VENDOR / "gymnasium").is_dir():
        pytest.fail(f"Gymnasium and PettingZoo's sources are not in {VENDOR} "
                    "(set CAMCOV_VENDOR_PYTHON)", pytrace=False)
    sys.path.insert(0, str(VENDOR))
    import camcov.env
    return camcov.env


def still(scene, count=None):
    return np.zeros((len(scene.cameras) if count is None else count, 3))


def test_stepping_before_reset_raises_and_says_reset(dynamic, envs):
    vector = envs.VectorCoverageEnv(dynamic, 2, params=SHORT)
    with pytest.raises(RuntimeError, match=r"episodes\[0\] is None.*call reset\(\) first"):
        vector.step(np.zeros(vector.action_space.shape))
    stepper = camcov.EpisodeStepper(1)
    sizes = camcov.encoding_sizes(dynamic)
    with pytest.raises(RuntimeError, match="call reset"):
        stepper.step([None], np.zeros((1, sizes[0], 3)), sizes)
    with pytest.raises(TypeError, match=r"episodes\[0\]: expected a camcov.Episode, got str"):
        stepper.step(["episode"], np.zeros((1, sizes[0], 3)), sizes)
    with pytest.raises(RuntimeError, match="call reset"):
        camcov.MethodPolicy("paper", None, 1)
    with pytest.raises(TypeError, match="episode: expected a camcov.Episode, got int"):
        camcov.MethodPolicy("paper", 3, 1)


def test_a_closed_episode_takes_no_step_and_no_decision(dynamic):
    episode = camcov.Episode(dynamic, SHORT)
    policy = camcov.MethodPolicy("paper", episode, 1)
    episode.step(still(dynamic))
    episode.close()
    with pytest.raises(RuntimeError, match="step: the episode is closed"):
        episode.step(still(dynamic))
    with pytest.raises(RuntimeError, match="decide: the episode is closed"):
        policy.decide(episode)
    stepper = camcov.EpisodeStepper(2)
    sizes = camcov.encoding_sizes(dynamic)
    with pytest.raises(RuntimeError, match=r"episodes\[0\]: the episode is closed"):
        stepper.step([episode], np.zeros((1, sizes[0], 3)), sizes)
    assert episode.index == 1  # what it reached before closing, still readable
    assert episode.observation(sizes).shape == (camcov.Episode(dynamic).observation(sizes).size,)


def test_a_finished_episode_takes_no_step(dynamic):
    episode = camcov.Episode(dynamic, {"sim.duration": 0.2})
    while not episode.finished:
        episode.step(still(dynamic))
    with pytest.raises(ValueError, match="step: the episode is finished"):
        episode.step(still(dynamic))
    episode.close()
    with pytest.raises(RuntimeError, match="closed"):
        episode.step(still(dynamic))


def test_an_episode_twice_or_too_small_sizes_in_a_batch_step_are_refused_before_any_step(dynamic):
    a, b = camcov.Episode(dynamic, SHORT), camcov.Episode(dynamic, SHORT)
    sizes = camcov.encoding_sizes(dynamic)
    stepper = camcov.EpisodeStepper(3)
    with pytest.raises(ValueError, match="episodes: 0 and 2 are the same episode"):
        stepper.step([a, b, a], np.zeros((3, sizes[0], 3)), sizes)
    assert (a.index, b.index) == (0, 0)
    cameras, targets, obstacles, vertices = sizes
    with pytest.raises(ValueError, match="more than the encoding holds"):
        stepper.step([a, b], np.zeros((2, cameras, 3)), (cameras, targets, obstacles, vertices - 1))
    assert (a.index, b.index) == (0, 0)
    stepper.step([a, b], np.zeros((2, sizes[0], 3)), sizes)  # the stepper still serves
    assert (a.index, b.index) == (1, 1)


def test_a_policy_refuses_an_episode_of_another_scene(dynamic, static):
    policy = camcov.MethodPolicy("paper", camcov.Episode(dynamic, SHORT), 1)
    with pytest.raises(ValueError, match="decide: an episode of scene 'tiny_static', but this "
                                         "policy was made for an episode of scene "
                                         "'tiny_dynamic'"):
        policy.decide(camcov.Episode(static, SHORT))
    # The episode it was made for lives as long as the policy, which still decides for an
    # episode of its scene.
    assert policy.decide(camcov.Episode(dynamic, SHORT)).shape == (len(dynamic.cameras), 3)


def test_a_parallel_step_missing_agents_names_them(static, envs):
    parallel = envs.CoverageParallelEnv(static, params=SHORT)
    parallel.reset(seed=0)
    with pytest.raises(ValueError, match=r"no command for agents \['camera_1'\]"):
        parallel.step({"camera_0": [0.0, 0.0, 0.0]})
    assert parallel.episodes.episode.index == 0


def test_wrong_types_get_camcov_messages_not_the_bindings(dynamic):
    with pytest.raises(TypeError, match="scene: expected a camcov.Scene, got NoneType"):
        camcov.Episode(None)
    with pytest.raises(TypeError, match="params: expected a dict"):
        camcov.parameters([("sim.dt", 0.1)])
    with pytest.raises(TypeError, match="params: expected a dict"):
        camcov.Episode(dynamic, "sim.duration=3")
    visibility = camcov.Visibility(dynamic.world_at(0.0), dynamic)
    with pytest.raises(TypeError, match="poses: expected numbers, got str"):
        visibility.terms([["a", 0.0, 0.0]])
    with pytest.raises(TypeError, match="duration: expected numbers, got str"):
        camcov.bench(scenes=[], duration="long")

    def words(observation):
        return [["fast", 0.0, 0.0]]

    with pytest.raises(TypeError, match="expected numbers, got str") as raised:
        camcov.simulate(str(REPO / "tests" / "data" / "scenes" / "tiny_dynamic.json"), words,
                        params={"sim.duration": 0.5})
    assert "Unable to cast" not in str(raised.value)


def hammer(threads, work):
    """Runs work(t) on `threads` threads at once; returns what each returned, raising the
    first failure."""
    results, failures = [None] * threads, []
    start = threading.Barrier(threads)

    def run(t):
        start.wait()
        try:
            results[t] = work(t)
        except BaseException as error:  # noqa: BLE001 (re-raised below, in the test's thread)
            failures.append(error)

    workers = [threading.Thread(target=run, args=(t,)) for t in range(threads)]
    for w in workers:
        w.start()
    for w in workers:
        w.join()
    if failures:
        raise failures[0]
    return results


def test_one_episode_shared_by_threads_moves_one_instant_per_step(dynamic):
    episode = camcov.Episode(dynamic, SHORT)
    sizes = camcov.encoding_sizes(dynamic)

    def work(t):
        stepped = 0
        while True:
            episode.observation(sizes)
            episode.terms, episode.cameras, episode.summary, episode.own_terms(0)
            if t == 0:
                episode.frame(32, 24)
            try:
                episode.step(still(dynamic))
                stepped += 1
            except ValueError:  # finished, by this thread or another
                return stepped

    stepped = hammer(6, work)
    assert sum(stepped) == episode.steps == episode.index


def test_one_stepper_and_one_policy_shared_by_threads_serve_each_in_turn(dynamic):
    sizes = camcov.encoding_sizes(dynamic)
    for trial in range(3):
        stepper = camcov.EpisodeStepper(3)
        shared = camcov.Episode(dynamic, SHORT)  # in every thread's batch
        policy = camcov.MethodPolicy("paper", shared, 1)

        def work(t):
            own = [camcov.Episode(dynamic, SHORT) for _ in range(3)]
            stepped = 0
            while True:
                if t == 0:
                    policy.decide(shared)
                try:
                    stepper.step(own + [shared], np.zeros((4, sizes[0], 3)), sizes)
                    stepped += 1
                except ValueError:  # `shared` finished
                    return stepped

        stepped = hammer(4, work)
        assert sum(stepped) == shared.steps == shared.index


def test_one_environment_shared_by_threads_steps_one_call_at_a_time(dynamic, envs):
    single = envs.CoverageEnv(dynamic, params=SHORT)
    single.reset(seed=1)

    def work_single(t):
        stepped = 0
        for _ in range(40):
            try:
                single.step(np.zeros(single.action_space.shape))
                stepped += 1
            except RuntimeError:  # another thread's step ended the episode
                return stepped
        return stepped

    stepped = hammer(4, work_single)
    assert sum(stepped) == single.episodes.episode.steps and single.episodes.episode.finished

    vector = envs.VectorCoverageEnv(dynamic, 3, threads=2, params=SHORT)
    vector.reset(seed=1)
    actions = np.zeros(vector.action_space.shape)

    def work_vector(t):
        for k in range(40):
            if t == 0 and k % 10 == 0:
                vector.reset(seed=k)
            vector.step(actions)

    hammer(4, work_vector)
    observations, *_ = vector.step(actions)
    assert observations.shape == vector.observation_space.shape


def test_one_visibility_shared_by_threads_gives_what_it_gives_alone(dynamic):
    visibility = camcov.Visibility(dynamic.world_at(1.0), dynamic)
    teams = [dynamic.initial_poses + [0.1 * k, 0.0, 0.05 * k] for k in range(8)]
    alone = [visibility.terms(team)["coverage"] for team in teams]
    shared = hammer(4, lambda t: [visibility.terms(team)["coverage"] for team in teams])
    assert all(result == alone for result in shared)
