"""camcov as environments for learning: Gymnasium and PettingZoo, and camcov's methods as policies.

    env = camcov.env.CoverageEnv("../shared/coverage_scenes/dynamic9.json")
    observation, info = env.reset(seed=1)
    paper = camcov.env.policy("paper", env)          # the paper's method, as camcov run runs it
    while True:
        observation, reward, terminated, truncated, info = env.step(paper(observation))
        if terminated or truncated:
            break

- CoverageEnv(scene, **options): a gymnasium.Env. The team's commands in one action.
- CoverageParallelEnv(scene, **options): a pettingzoo.ParallelEnv, one agent per camera.
- VectorCoverageEnv(scene, num_envs, threads=None, **options): a gymnasium.vector.VectorEnv
  stepping its episodes in C++ threads without the GIL.
- policy(method, env): a method of camcov's table (camcov.methods()) choosing the commands.
- family(name, split="tune", count=20): the scenes of a generated family (docs/families.md).

`scene` is a scene file, a camcov.Scene, or a list of them (a family's): reset() picks one with
its seeded generator (options={"scene": i} picks scene i). Gymnasium and PettingZoo are
imported only when their environments are first used; camcov itself needs neither.
The observation layout, the options and the rewards: docs/python.md, "Environments".
"""
import functools
import os
import threading

import numpy as np

import camcov

__all__ = ["CoverageEnv", "CoverageParallelEnv", "VectorCoverageEnv", "policy", "family",
           "Episodes"]

# The environments' classes live in modules that import gymnasium or pettingzoo: loaded on
# first use, so that `import camcov.env` and policy() need neither.
_LAZY = {"CoverageEnv": "camcov._gym_env", "VectorCoverageEnv": "camcov._vector_env",
         "CoverageParallelEnv": "camcov._parallel_env"}


def __getattr__(name):
    if name in _LAZY:
        import importlib
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'camcov.env' has no attribute {name!r}")


def one_call_at_a_time(method):
    """An environment's reset() or step() that takes turns with the others so marked on the
    same environment: Python threads sharing one environment use it one call at a time (its
    episodes' own locks keep the native state safe; this keeps the environment's Python state
    whole too)."""
    @functools.wraps(method)
    def taking_turns(self, *args, **kwargs):
        with self.__dict__.setdefault("_one_call_at_a_time", threading.RLock()):
            return method(self, *args, **kwargs)
    return taking_turns


def family(name, split="tune", count=20):
    """The first `count` scenes of family `name`'s tune or test seeds, as camcov.Scene objects:
    the scenes `camcov generate --family NAME` writes for those seeds."""
    families = camcov.families()
    if name not in families:
        raise ValueError(f"family: no family {name!r}; known: {', '.join(families)}")
    if split not in ("tune", "test"):
        raise ValueError(f"split: expected 'tune' or 'test', got {split!r}")
    first, last = families[name][split]
    if not isinstance(count, int) or not 1 <= count <= last - first + 1:
        raise ValueError(f"count: expected 1 to {last - first + 1} scenes, got {count!r}")
    return [camcov.family_scene(name, seed) for seed in range(first, first + count)]


def _scene_list(scene):
    """scene (a file, a camcov.Scene, or a non-empty list of them) as a list of camcov.Scene."""
    items = list(scene) if isinstance(scene, (list, tuple)) else [scene]
    if not items:
        raise ValueError("scene: expected a scene file, a camcov.Scene or a list of them; "
                         "the list is empty")
    scenes = []
    for item in items:
        if isinstance(item, camcov.Scene):
            scenes.append(item)
        elif isinstance(item, (str, os.PathLike)):
            scenes.append(camcov.load_scene(os.fspath(item)))
        else:
            raise TypeError(f"scene: expected a scene file, a camcov.Scene or a list of them, "
                            f"got {type(item).__name__}")
    return scenes


class Episodes:
    """What every environment of camcov.env shares: the scenes, the parameters, the sizes
    observations pad to, and the episode now running (a camcov.Episode). Not an environment
    itself; the environments hold one."""

    REWARDS = ("reward", "coverage")

    def __init__(self, scene, params=None, reward="reward"):
        """Loads the scenes and checks the parameters and the reward's name."""
        self.scenes = _scene_list(scene)
        if reward not in self.REWARDS:
            raise ValueError(f"reward: expected one of {self.REWARDS}, got {reward!r}")
        self.reward_term = reward
        self.params = dict(params or {})
        # Bad keys or values raise here, not at the first reset.
        resolved = camcov.parameters(self.params)
        # The coverage the reward takes: weighted by the scene's importance weights, if any,
        # unless reward.weighted is off (where a scene has none, the two are equal).
        self.coverage_key = "weightedCoverage" if resolved["reward"]["weighted"] else "coverage"
        sizes = np.zeros(4, dtype=np.int64)
        for s in self.scenes:
            sizes = np.maximum(sizes, camcov.encoding_sizes(s))
        self.sizes = tuple(int(v) for v in sizes)  # cameras, targets, obstacles, vertices
        # Per camera slot: the largest v_max and yaw rate of any scene's camera in that slot.
        self.limits = np.zeros((self.sizes[0], 3))
        for s in self.scenes:
            for j, c in enumerate(s.cameras):
                v, w = c["maxVelocity"], c["maxAngularVelocity"]
                self.limits[j] = np.maximum(self.limits[j], [v, v, w])
        self.episode = None
        self.scene_index = -1
        self.seed = None      # the run seed of the episode now running (policy() uses it)
        self.count = 0        # episodes started: a policy makes its controller anew for each

    @property
    def observation_size(self):
        """Floats in an observation: the layout of docs/python.md at these sizes."""
        cameras, targets, obstacles, vertices = self.sizes
        return 4 + 10 * cameras + (5 + 2 * vertices) * targets + (2 + 2 * vertices) * obstacles

    def start(self, rng, options):
        """A new episode: the scene options["scene"] if given, else one drawn with `rng`; the
        run seed options["seed"] if given, else drawn with `rng`. Other keys are ignored."""
        options = options or {}  # other keys are not camcov's (wrappers pass their own)
        index = options.get("scene")
        if index is None:
            index = int(rng.integers(len(self.scenes))) if len(self.scenes) > 1 else 0
        if not isinstance(index, (int, np.integer)) or not 0 <= index < len(self.scenes):
            raise ValueError(f"options['scene']: expected 0 to {len(self.scenes) - 1}, "
                             f"got {index!r}")
        seed = options.get("seed")
        self.seed = int(rng.integers(1, 2**31)) if seed is None else int(seed)
        self.scene_index = int(index)
        self.episode = camcov.Episode(self.scenes[self.scene_index], self.params)
        self.count += 1
        return self.episode

    def cameras(self):
        """How many cameras the running episode's scene has."""
        return len(self.episode.scene.cameras)

    def reward(self, terms):
        """The step's reward from a dict of terms: the one chosen (eq. 8 or eq. 3)."""
        key = self.coverage_key if self.reward_term == "coverage" else self.reward_term
        return float(terms[key])

    def info(self, terms=None):
        """The step's info dict: time, scene, run seed, the terms; at the end the summary (the
        episode is closed for it)."""
        episode = self.episode
        terms = episode.terms if terms is None else terms
        info = {"time": episode.time, "scene": episode.scene.name, "seed": self.seed,
                "coverage": terms["coverage"], "weightedCoverage": terms["weightedCoverage"],
                "utilization": terms["utilization"],
                "repulsion": terms["repulsion"], "reward": terms["reward"]}
        if episode.finished:
            episode.close()
            info["summary"] = episode.summary
        return info


class _MethodPolicy:
    """A method of camcov's table choosing an environment's commands (see policy())."""

    def __init__(self, method, env):
        """A policy of `env` by method `method` (a name of camcov.methods())."""
        names = [m["name"] for m in camcov.methods()]
        if method not in names:
            raise ValueError(f"method: no method {method!r}; known: {', '.join(names)}")
        self.method = method
        self.env = env
        self._controllers = {}  # per episode (an environment's, or each of a vector's)

    def _commands(self, episodes):
        """The commands, (cameras, 3), for the running episode of `episodes`."""
        key = id(episodes)
        made = self._controllers.get(key)
        if made is None or made[0] != episodes.count:
            made = (episodes.count, camcov.MethodPolicy(self.method, episodes.episode,
                                                        episodes.seed))
            self._controllers[key] = made
        return made[1].decide(episodes.episode)

    def _padded(self, episodes):
        action = np.zeros((episodes.sizes[0], 3))
        commands = self._commands(episodes)
        action[:len(commands)] = commands
        return action

    def __call__(self, observation=None):
        """The action for the environment's present instant (the observation is not read: the
        method sees the world itself, as in camcov run)."""
        env = getattr(self.env, "unwrapped", self.env)
        if hasattr(env, "vector_episodes"):
            return np.stack([self._padded(e) for e in env.vector_episodes])
        if hasattr(env, "possible_agents"):
            commands = self._commands(env.episodes)
            return {agent: commands[j] for j, agent in enumerate(env.agents)}
        return self._padded(env.episodes)


def policy(method, env):
    """camcov's method `method` (a name of camcov.methods(): "paper", "local", "camcov", or
    one registered) as a policy of `env` (any environment of camcov.env, wrapped or not):
    policy(observation) -> action. Its controller is made for each episode with the episode's
    scene, parameters and run seed (info["seed"]; reset(options={"seed": s}) sets it), so an
    episode driven by policy("paper", env) is `camcov run --method paper --seed s`, step for
    step."""
    return _MethodPolicy(method, env)
