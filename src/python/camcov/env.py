"""camcov as environments for learning: Gymnasium and PettingZoo, and camcov's methods as policies.

    env = gymnasium.make("camcov/Coverage-v0", scene="../shared/coverage_scenes/dynamic9.json")
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
- make(id, **options): either environment by its registered id (IDS).
- policy(method, env): a method of camcov's table (camcov.methods()) choosing the commands.
- family(name, split="tune", count=20): the scenes of a generated family (docs/families.md).

`scene` is a scene file, a camcov.Scene, or a list of them (a family's): reset() picks one with
its seeded generator (options={"scene": i} picks scene i). Importing camcov.env registers
"camcov/Coverage-v0" with Gymnasium where Gymnasium is installed (gymnasium.make, make_vec);
camcov itself needs neither Gymnasium nor PettingZoo.
The observation layout, the options and the rewards: docs/python.md, "Environments".
"""
import functools
import os
import threading

import numpy as np

import camcov

__all__ = ["CoverageEnv", "CoverageParallelEnv", "VectorCoverageEnv", "make", "policy",
           "family", "Episodes", "IDS", "MethodAction", "commands_of"]

# The environments' classes live in modules that import gymnasium or pettingzoo: loaded on
# first use, so that `import camcov.env` and policy() need neither.
_LAZY = {"CoverageEnv": "camcov._gym_env", "VectorCoverageEnv": "camcov._vector_env",
         "CoverageParallelEnv": "camcov._parallel_env"}


def __getattr__(name):
    if name in _LAZY:
        import importlib
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'camcov.env' has no attribute {name!r}")


# The registered ids: Gymnasium's registry takes the single environment (its vector entry point
# the threaded VectorCoverageEnv, which make_vec uses); PettingZoo has no registry and
# gymnasium.make makes only gymnasium.Env, so the multi-agent id is made by make() below.
IDS = {"camcov/Coverage-v0": "camcov._gym_env:CoverageEnv",
       "camcov/CoverageParallel-v0": "camcov._parallel_env:CoverageParallelEnv"}
_VECTOR_ENTRY_POINT = "camcov._vector_env:VectorCoverageEnv"


def _register_with_gymnasium():
    """Registers camcov/Coverage-v0 where Gymnasium is installed (once)."""
    try:
        import gymnasium
    except ImportError:
        return
    name = "camcov/Coverage-v0"
    if name not in gymnasium.registry:
        gymnasium.register(name, entry_point=IDS[name], vector_entry_point=_VECTOR_ENTRY_POINT)


_register_with_gymnasium()


def make(id, **options):
    """The environment of a registered id (IDS) with its options, e.g.
    make("camcov/CoverageParallel-v0", scene="dynamic9.json", view="own"):
    "camcov/Coverage-v0" through gymnasium.make (with its wrappers), the parallel one directly."""
    if id not in IDS:
        raise ValueError(f"id: expected one of {', '.join(IDS)}, got {id!r}")
    if id == "camcov/Coverage-v0":
        import gymnasium
        return gymnasium.make(id, **options)
    return __getattr__("CoverageParallelEnv")(**options)


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
    observations pad to, how actions scale, and the episode now running (a camcov.Episode).
    Not an environment itself; the environments hold one."""

    REWARDS = ("reward", "coverage")
    INFO_KEYS = ("time", "scene", "seed", "coverage", "weightedCoverage", "utilization",
                 "repulsion", "reward")
    FINAL_INFO_KEYS = ("summary", "average_coverage")
    ACTION_UNITS = ("normalized", "physical")
    PADDED = ("cameras", "obstacles", "vertices")

    def __init__(self, scene, params=None, reward="reward", action_units="normalized",
                 targets=None, pad_to=None):
        """Loads the scenes and checks the options (the environments' docstrings say them)."""
        self.scenes = _scene_list(scene)
        if reward not in self.REWARDS:
            raise ValueError(f"reward: expected one of {self.REWARDS}, got {reward!r}")
        if action_units not in self.ACTION_UNITS:
            raise ValueError(f"action_units: expected one of {self.ACTION_UNITS}, got "
                             f"{action_units!r}")
        self.reward_term = reward
        self.action_units = action_units
        self.params = dict(params or {})
        # Bad keys or values raise here, not at the first reset.
        resolved = camcov.parameters(self.params)
        # The coverage the reward takes: weighted by the scene's importance weights, if any,
        # unless reward.weighted is off (where a scene has none, the two are equal).
        self.coverage_key = "weightedCoverage" if resolved["reward"]["weighted"] else "coverage"
        sizes = np.zeros(4, dtype=np.int64)
        for s in self.scenes:
            sizes = np.maximum(sizes, camcov.encoding_sizes(s))
        sizes = [int(v) for v in sizes]  # cameras, targets, obstacles, vertices
        self.target_slots = "index"
        if targets is not None:
            if not isinstance(targets, (int, np.integer)) or not 1 <= targets <= 10000:
                raise ValueError(f"targets: expected None or a number of targets from 1 to "
                                 f"10000, got {targets!r}")
            sizes[1], self.target_slots = int(targets), "nearest"
        for key, value in dict(pad_to or {}).items():
            if key not in self.PADDED:
                raise ValueError(f"pad_to: expected keys among {self.PADDED}, got {key!r}")
            at = {"cameras": 0, "obstacles": 2, "vertices": 3}[key]
            if not isinstance(value, (int, np.integer)) or not sizes[at] <= value <= 10000:
                raise ValueError(f"pad_to[{key!r}]: expected {sizes[at]} (what the scenes "
                                 f"need) to 10000, got {value!r}")
            sizes[at] = int(value)
        self.sizes = tuple(sizes)
        # Per camera slot, per scene: v_max, v_max and the yaw rate limit of the scene's camera
        # in that slot (zeros past its cameras); a normalized action is scaled by them.
        self.scene_limits = []
        for s in self.scenes:
            limits = np.zeros((self.sizes[0], 3))
            for j, c in enumerate(s.cameras):
                v, w = c["maxVelocity"], c["maxAngularVelocity"]
                limits[j] = [v, v, w]
            self.scene_limits.append(limits)
        # Per camera slot: the largest limits of any scene's camera in that slot.
        self.limits = np.max(self.scene_limits, axis=0)
        self.episode = None
        self.scene_index = -1
        self.seed = None      # the run seed of the episode now running (policy() uses it)
        self.count = 0        # episodes started: a policy makes its controller anew for each

    def observation_bounds(self):
        """(low, high), float32: the bounds of every float of an observation."""
        return camcov.observation_bounds(self.sizes)

    def observation(self, view="team", camera=0):
        """The running episode's present instant encoded (docs/python.md)."""
        return self.episode.observation(self.sizes, view, camera, self.target_slots)

    def action_bounds(self):
        """(low, high) of a team action, (camera slots, 3): [-1, 1] normalized, else each
        slot's largest limits in m/s and rad/s."""
        if self.action_units == "normalized":
            ones = np.ones((self.sizes[0], 3), dtype=np.float32)
            return -ones, ones
        return -self.limits, self.limits

    @property
    def action_dtype(self):
        """float32 for normalized actions, float64 for physical ones."""
        return np.float32 if self.action_units == "normalized" else np.float64

    @property
    def action_scale(self):
        """What an action's rows are multiplied by to give the running scene's commands in
        m/s and rad/s, (camera slots, 3): its cameras' limits if normalized (so 1 is the
        camera's own limit), else ones."""
        if self.action_units == "normalized":
            return self.scene_limits[self.scene_index]
        return np.ones((self.sizes[0], 3))

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
        """The step's info dict (INFO_KEYS): time, scene, run seed, the terms; at the end also
        the summary and its average coverage, eq. (4) (FINAL_INFO_KEYS; the episode is closed
        for them)."""
        episode = self.episode
        terms = episode.terms if terms is None else terms
        info = {"time": episode.time, "scene": episode.scene.name, "seed": self.seed,
                "coverage": terms["coverage"], "weightedCoverage": terms["weightedCoverage"],
                "utilization": terms["utilization"],
                "repulsion": terms["repulsion"], "reward": terms["reward"]}
        if episode.finished:
            episode.close()
            info["summary"] = episode.summary
            info["average_coverage"] = info["summary"]["averageCoverage"]
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
            episodes = env.vector_episodes
            return MethodAction.of(np.stack([self._padded(e) for e in episodes]),
                                   np.stack([e.action_scale for e in episodes]))
        if hasattr(env, "possible_agents"):
            commands, scale = self._commands(env.episodes), env.episodes.action_scale
            return {agent: MethodAction.of(commands[j], scale[j])
                    for j, agent in enumerate(env.agents[:len(commands)])}
        return MethodAction.of(self._padded(env.episodes), env.episodes.action_scale)


class MethodAction(np.ndarray):
    """A method's action: in the environment's units like any other (normalized: the commands
    over the cameras' limits, float32), and carrying the commands in m/s and rad/s it was made
    from, which the environments step as they are: a division and a multiplication by the
    limits would round, and a method's episode is its camcov run to the bit."""

    physical = None

    @staticmethod
    def of(commands, scale):
        """The action of `commands` (m/s, rad/s) under `scale` (Episodes.action_scale)."""
        if np.all(scale == 1.0):
            return commands
        normalized = np.divide(commands, scale, out=np.zeros_like(commands), where=scale > 0)
        action = normalized.astype(np.float32).view(MethodAction)
        action.physical = commands
        return action


def commands_of(action, scale, shape, what):
    """The commands in m/s and rad/s, float64 of `shape`, of an environment's action: a
    MethodAction's own, else the action times `scale` (Episodes.action_scale). ValueError
    naming `what` for another shape; the simulator refuses numbers that are not finite."""
    physical = getattr(action, "physical", None)
    if physical is not None:
        return physical
    action = np.asarray(action, dtype=np.float64)
    if action.shape != shape:
        raise ValueError(f"{what}: expected shape {shape} (vx, vy, yaw rate per camera), got "
                         f"{action.shape}")
    return action * scale


def policy(method, env):
    """camcov's method `method` (a name of camcov.methods(): "paper", "local", "camcov", or
    one registered) as a policy of `env` (any environment of camcov.env, wrapped or not):
    policy(observation) -> action. Its controller is made for each episode with the episode's
    scene, parameters and run seed (info["seed"]; reset(options={"seed": s}) sets it), so an
    episode driven by policy("paper", env) is `camcov run --method paper --seed s`, step for
    step."""
    return _MethodPolicy(method, env)
