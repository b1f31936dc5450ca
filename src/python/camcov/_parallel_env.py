"""camcov.env.CoverageParallelEnv: a PettingZoo environment (imported by camcov.env on first use)."""
import numpy as np
from gymnasium import spaces
from pettingzoo import ParallelEnv

from camcov.env import Episodes, one_call_at_a_time


class CoverageParallelEnv(ParallelEnv):
    """camcov's simulator as a PettingZoo ParallelEnv: one agent per camera ("camera_0", …).

    CoverageParallelEnv(scene, params=None, reward="reward", view="team",
                        agent_reward="team", render_mode=None, render_size=(640, 480))

    - scene, params, reward: as CoverageEnv's.
    - view: "team" (each agent observes the team's observation, the layout of docs/python.md)
      or "own" (only what its camera sees: its own slot first, no other camera, no obstacle,
      the targets it sees some of), for decentralized policies.
    - agent_reward: "team" (each agent gets the team's reward) or "own" (its camera's own
      terms, as if it were alone: camcov.Episode.own_terms).
    - action per agent: (3,) float64, vx, vy (m/s), yaw rate (rad/s), within the largest
      limits of that camera slot; the simulator saturates to the camera's own.
    The agents are the running scene's cameras; all are truncated together at sim.duration.
    state() is the team's observation (for centralized critics).
    """

    metadata = {"render_modes": ["rgb_array"], "name": "camcov_coverage_v0", "render_fps": 10}

    def __init__(self, scene, params=None, reward="reward", view="team", agent_reward="team",
                 render_mode=None, render_size=(640, 480)):
        """The environment of the scenes, with the options of the class's docstring."""
        self.episodes = Episodes(scene, params, reward)
        if view not in ("team", "own"):
            raise ValueError(f"view: expected 'team' or 'own', got {view!r}")
        if agent_reward not in ("team", "own"):
            raise ValueError(f"agent_reward: expected 'team' or 'own', got {agent_reward!r}")
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: expected None or 'rgb_array', got {render_mode!r}")
        from camcov._gym_env import _image_size
        self.render_size = _image_size(render_size, "render_size")
        self.view = view
        self.agent_reward = agent_reward
        self.render_mode = render_mode
        self.possible_agents = [f"camera_{j}" for j in range(self.episodes.sizes[0])]
        self.agents = []
        size = self.episodes.observation_size
        # One space object per agent, every call (PettingZoo seeds spaces through them).
        self.observation_spaces = {a: spaces.Box(-np.inf, np.inf, (size,), np.float32)
                                   for a in self.possible_agents}
        self.action_spaces = {a: spaces.Box(-self.episodes.limits[j], self.episodes.limits[j],
                                            dtype=np.float64)
                              for j, a in enumerate(self.possible_agents)}
        self.state_space = spaces.Box(-np.inf, np.inf, (size,), np.float32)
        self._rng = np.random.default_rng()

    def observation_space(self, agent):
        """The Box of an agent's observations."""
        return self.observation_spaces[agent]

    def action_space(self, agent):
        """The Box of an agent's commands: vx, vy (m/s), yaw rate (rad/s)."""
        return self.action_spaces[agent]

    def _observations(self):
        episode, sizes = self.episodes.episode, self.episodes.sizes
        if self.view == "team":
            team = episode.observation(sizes)
            return {agent: team.copy() for agent in self.agents}
        return {agent: episode.observation(sizes, "own", j) for j, agent in enumerate(self.agents)}

    def _rewards(self, terms):
        if self.agent_reward == "team":
            value = self.episodes.reward(terms)
            return {agent: value for agent in self.agents}
        episode = self.episodes.episode
        return {agent: self.episodes.reward(episode.own_terms(j))
                for j, agent in enumerate(self.agents)}

    @one_call_at_a_time
    def reset(self, seed=None, options=None):
        """Starts an episode at t = 0: (observations, infos), one entry per agent."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self.episodes.start(self._rng, options)
        self.agents = self.possible_agents[:self.episodes.cameras()]
        info = self.episodes.info()
        return self._observations(), {agent: dict(info) for agent in self.agents}

    @one_call_at_a_time
    def step(self, actions):
        """One step of sim.dt with every live agent's command (ValueError naming any missing):
        (observations, rewards, terminations, truncations, infos)."""
        episode = self.episodes.episode
        if episode is None or not self.agents:
            raise RuntimeError("step: call reset() first; the episode is over")
        if not isinstance(actions, dict):
            raise TypeError(f"actions: expected a dict agent -> (3,) command, got "
                            f"{type(actions).__name__}")
        unknown = set(actions) - set(self.agents)
        if unknown:
            raise ValueError(f"actions: no agents {sorted(unknown)} in {self.agents}")
        commands = np.zeros((len(self.agents), 3))
        for j, agent in enumerate(self.agents):
            if agent in actions:
                command = np.asarray(actions[agent], dtype=np.float64)
                if command.shape != (3,):
                    raise ValueError(f"actions[{agent!r}]: expected shape (3,) (vx, vy, yaw "
                                     f"rate), got {command.shape}")
                commands[j] = command
        missing = [agent for agent in self.agents if agent not in actions]
        if missing:
            raise ValueError(f"actions: no command for agents {missing}; every live agent "
                             f"gives one")
        episode.step(commands)
        observations = self._observations()
        terms = episode.terms
        rewards = self._rewards(terms)
        over = episode.finished
        info = self.episodes.info(terms)
        agents = self.agents
        if over:
            self.agents = []
        return (observations, rewards, {a: False for a in agents}, {a: over for a in agents},
                {a: dict(info) for a in agents})

    def state(self):
        """The team's observation now (the layout of docs/python.md)."""
        return self.episodes.episode.observation(self.episodes.sizes)

    def render(self):
        """The present instant as camcov render draws it, (height, width, 3) uint8 RGB, for
        render_mode "rgb_array"; None otherwise."""
        if self.render_mode != "rgb_array" or self.episodes.episode is None:
            return None
        return self.episodes.episode.frame(*self.render_size)

    def close(self):
        """Nothing to release: episodes free themselves."""
