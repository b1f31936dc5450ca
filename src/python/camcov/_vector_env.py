"""camcov.env.VectorCoverageEnv: many episodes stepped in C++ threads (imported on first use)."""
import os

import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

import camcov
from camcov._gym_env import _action_space, _observation_space
from camcov.env import Episodes, commands_of, one_call_at_a_time


MAX_ENVS = 65536  # each holds a simulation; more would exhaust memory before stepping once


class VectorCoverageEnv(VectorEnv):
    """num_envs CoverageEnv episodes stepped together in C++ threads, without the GIL: a
    gymnasium.vector.VectorEnv with next-step autoreset (the step after an episode ends
    starts the next one and ignores that row of actions).

    VectorCoverageEnv(scene, num_envs, threads=None, params=None, reward="reward",
                      action_units="normalized", targets=None, pad_to=None)

    scene, params, reward, action_units, targets and pad_to as CoverageEnv's (vector
    observations only); threads: how many to step on (default: the machine's cores, at most
    num_envs). Actions (num_envs, cameras, 3); observations (num_envs, size) float32.
    reset(seed=s) seeds environment i with s + i. infos: CoverageEnv's keys, each an array of
    num_envs with its mask "_key" as Gymnasium's vector environments give them ("summary"
    and "average_coverage" only where an episode ended).
    """

    metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(self, scene, num_envs, threads=None, params=None, reward="reward",
                 action_units="normalized", targets=None, pad_to=None):
        """num_envs episodes of the scenes, stepped on `threads` threads."""
        if not isinstance(num_envs, int) or not 1 <= num_envs <= MAX_ENVS:
            raise ValueError(f"num_envs: expected a whole number from 1 to {MAX_ENVS}, got "
                             f"{num_envs!r}")
        if threads is None:
            threads = min(num_envs, os.cpu_count() or 1, 256)
        if not isinstance(threads, int) or not 1 <= threads <= 256:
            raise ValueError(f"threads: expected a whole number from 1 to 256, got {threads!r}")
        options = (params, reward, action_units, targets, pad_to)
        scenes = Episodes(scene, *options).scenes  # loaded once, shared by all
        self.vector_episodes = [Episodes(scenes, *options) for _ in range(num_envs)]
        self.num_envs = num_envs
        self.stepper = camcov.EpisodeStepper(threads)
        first = self.vector_episodes[0]
        self.single_observation_space = _observation_space(first)
        self.single_action_space = _action_space(first)
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self._rngs = [np.random.default_rng() for _ in range(num_envs)]
        self._ended = np.zeros(num_envs, dtype=bool)
        # Each environment's Episodes.action_scale, a row each, kept as episodes start.
        self._scales = np.ones(self.action_space.shape)

    def _start(self, i, options=None):
        episodes = self.vector_episodes[i]
        episodes.start(self._rngs[i], options)
        self._scales[i] = episodes.action_scale
        return episodes.observation()

    @one_call_at_a_time
    def reset(self, *, seed=None, options=None):
        """Starts every episode at t = 0: (observations, infos)."""
        if seed is not None:
            seeds = seed if isinstance(seed, (list, tuple)) else [seed + i
                                                                  for i in range(self.num_envs)]
            if len(seeds) != self.num_envs:
                raise ValueError(f"seed: expected one seed or {self.num_envs}, got {len(seeds)}")
            self._rngs = [np.random.default_rng(s) for s in seeds]
        observations = np.stack([self._start(i, options) for i in range(self.num_envs)])
        self._ended[:] = False
        return observations, self._infos()

    def _infos(self):
        """Each environment's Episodes.info() as Gymnasium's vector infos: per key an array of
        num_envs and its mask "_key" (the keys only some environments have: where they have
        them)."""
        each = [e.info() for e in self.vector_episodes]
        n = self.num_envs
        # The numbers in one table (an array for each key would cost a third of a step).
        numbers = [key for key in Episodes.INFO_KEYS if key not in ("scene", "seed")]
        table = np.array([[info[key] for key in numbers] for info in each])
        infos = {key: table[:, column] for column, key in enumerate(numbers)}
        infos["scene"] = np.array([info["scene"] for info in each], dtype=object)
        infos["seed"] = np.array([info["seed"] for info in each], dtype=np.int64)
        everywhere = np.ones(n, dtype=bool)
        everywhere.flags.writeable = False  # one mask for every key (each its own: a µs each)
        for key in Episodes.INFO_KEYS:
            infos["_" + key] = everywhere
        ended = np.array(["summary" in info for info in each])
        if ended.any():
            for key in Episodes.FINAL_INFO_KEYS:
                values = np.zeros(n, dtype=object if key == "summary" else np.float64)
                for i in np.flatnonzero(ended):
                    values[i] = each[i][key]
                infos[key], infos["_" + key] = values, ended.copy()
        return infos

    @one_call_at_a_time
    def step(self, actions):
        """One step of sim.dt in every environment: (observations, rewards, terminations,
        truncations, infos), each with num_envs rows."""
        commands = commands_of(actions, self._scales, self.action_space.shape, "actions")
        n = self.num_envs
        observations = np.zeros(self.observation_space.shape, np.float32)
        rewards = np.zeros(n)
        truncations = np.zeros(n, dtype=bool)
        stepping = np.flatnonzero(~self._ended)
        for i in np.flatnonzero(self._ended):  # next-step autoreset
            observations[i] = self._start(i)
        if len(stepping):
            first = self.vector_episodes[0]
            new, terms = self.stepper.step(
                [self.vector_episodes[i].episode for i in stepping], commands[stepping],
                first.sizes, first.target_slots)
            observations[stepping] = new
            column = 0 if first.reward_term == "coverage" else 3
            rewards[stepping] = terms[:, column]
            truncations[stepping] = [self.vector_episodes[i].episode.finished for i in stepping]
        self._ended = truncations
        return observations, rewards, np.zeros(n, dtype=bool), truncations, self._infos()
