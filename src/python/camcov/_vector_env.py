"""camcov.env.VectorCoverageEnv: many episodes stepped in C++ threads (imported on first use)."""
import os

import numpy as np
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

import camcov
from camcov._gym_env import _action_space
from camcov.env import Episodes, one_call_at_a_time
from gymnasium import spaces


MAX_ENVS = 65536  # each holds a simulation; more would exhaust memory before stepping once


class VectorCoverageEnv(VectorEnv):
    """num_envs CoverageEnv episodes stepped together in C++ threads, without the GIL: a
    gymnasium.vector.VectorEnv with next-step autoreset (the step after an episode ends
    starts the next one and ignores that row of actions).

    VectorCoverageEnv(scene, num_envs, threads=None, params=None, reward="reward")

    scene, params and reward as CoverageEnv's (vector observations only); threads: how many
    to step on (default: the machine's cores, at most num_envs). Actions (num_envs, cameras,
    3); observations (num_envs, size) float32. reset(seed=s) seeds environment i with s + i.
    infos: "coverage" and "time" per environment, and where an episode ended, "average_coverage"
    (eq. 4) with its mask "_average_coverage".
    """

    metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP}

    def __init__(self, scene, num_envs, threads=None, params=None, reward="reward"):
        """num_envs episodes of the scenes, stepped on `threads` threads."""
        if not isinstance(num_envs, int) or not 1 <= num_envs <= MAX_ENVS:
            raise ValueError(f"num_envs: expected a whole number from 1 to {MAX_ENVS}, got "
                             f"{num_envs!r}")
        if threads is None:
            threads = min(num_envs, os.cpu_count() or 1, 256)
        if not isinstance(threads, int) or not 1 <= threads <= 256:
            raise ValueError(f"threads: expected a whole number from 1 to 256, got {threads!r}")
        scenes = Episodes(scene, params, reward).scenes  # loaded once, shared by all
        self.vector_episodes = [Episodes(scenes, params, reward) for _ in range(num_envs)]
        self.num_envs = num_envs
        self.stepper = camcov.EpisodeStepper(threads)
        first = self.vector_episodes[0]
        self.single_observation_space = spaces.Box(-np.inf, np.inf, (first.observation_size,),
                                                   np.float32)
        self.single_action_space = _action_space(first)
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)
        self._rngs = [np.random.default_rng() for _ in range(num_envs)]
        self._ended = np.zeros(num_envs, dtype=bool)

    def _start(self, i, options=None):
        episodes = self.vector_episodes[i]
        episodes.start(self._rngs[i], options)
        return episodes.episode.observation(episodes.sizes)

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
        return {"coverage": np.array([e.episode.terms["coverage"] for e in self.vector_episodes]),
                "time": np.array([e.episode.time for e in self.vector_episodes])}

    @one_call_at_a_time
    def step(self, actions):
        """One step of sim.dt in every environment: (observations, rewards, terminations,
        truncations, infos), each with num_envs rows."""
        actions = np.asarray(actions, dtype=np.float64)
        if actions.shape != self.action_space.shape:
            raise ValueError(f"actions: expected shape {self.action_space.shape} (per "
                             f"environment, vx, vy, yaw rate per camera), got {actions.shape}")
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
                [self.vector_episodes[i].episode for i in stepping], actions[stepping],
                first.sizes)
            observations[stepping] = new
            column = 0 if first.reward_term == "coverage" else 3
            rewards[stepping] = terms[:, column]
            truncations[stepping] = [self.vector_episodes[i].episode.finished for i in stepping]
        infos = self._infos()
        average = np.zeros(n)
        for i in np.flatnonzero(truncations):
            episode = self.vector_episodes[i].episode
            episode.close()
            average[i] = episode.summary["averageCoverage"]
        if truncations.any():
            infos["average_coverage"], infos["_average_coverage"] = average, truncations.copy()
        self._ended = truncations
        return observations, rewards, np.zeros(n, dtype=bool), truncations, infos
