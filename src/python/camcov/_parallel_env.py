"""camcov.env.CoverageParallelEnv: a PettingZoo environment (imported by camcov.env on first use)."""
import numpy as np
from gymnasium import spaces
from pettingzoo import ParallelEnv

from camcov.env import Episodes, commands_of, one_call_at_a_time


class CoverageParallelEnv(ParallelEnv):
    """camcov's simulator as a PettingZoo ParallelEnv: one agent per camera ("camera_0", …).

    CoverageParallelEnv(scene, params=None, reward="reward", view="team",
                        agent_reward="team", render_mode=None, render_size=(640, 480),
                        action_units="normalized", targets=None, pad_to=None)

    - scene, params, reward, action_units, targets, pad_to: as CoverageEnv's.
    - view: "team" (each agent observes the team's observation, the layout of docs/python.md,
      followed by its id: one float per camera slot, 1 at its own) or "own" (egocentric: its
      own camera's slot first, its teammates after it, no obstacle, only the targets it sees
      some of), for decentralized policies, or "known" (what its camera knows, laid out as the
      team's observation with its own slot first: with params {"knowledge.limited": True} the
      world as it saw it or was told and its teammates where it last heard of them, the
      observation of a decentralized team; with full knowledge the team's).
    - agent_reward: "team" (each agent gets the team's reward) or "own" (its camera's own
      terms, as if it were alone: camcov.Episode.own_terms).
    - action per agent: (3,) vx, vy, yaw rate: normalized float32 in [-1, 1] (1: its camera's
      limit), or with action_units "physical" float64 in m/s and rad/s within the largest
      limits of that camera slot; the simulator saturates to the camera's own.
    The agents are the running scene's cameras, truncated together at sim.duration (with a
    family whose teams differ in size, the slots a scene has no camera for are agents that
    observe zeros and are terminated at the first step).
    state() is the team's observation (for centralized critics). Each agent's info has
    CoverageEnv's keys.
    """

    metadata = {"render_modes": ["rgb_array"], "name": "camcov_coverage_v0", "render_fps": 10}

    def __init__(self, scene, params=None, reward="reward", view="team", agent_reward="team",
                 render_mode=None, render_size=(640, 480), action_units="normalized",
                 targets=None, pad_to=None):
        """The environment of the scenes, with the options of the class's docstring."""
        self.episodes = Episodes(scene, params, reward, action_units, targets, pad_to)
        if view not in ("team", "own", "known"):
            raise ValueError(f"view: expected 'team', 'own' or 'known', got {view!r}")
        if agent_reward not in ("team", "own"):
            raise ValueError(f"agent_reward: expected 'team' or 'own', got {agent_reward!r}")
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: expected None or 'rgb_array', got {render_mode!r}")
        from camcov._gym_env import _image_size, _observation_space
        self.render_size = _image_size(render_size, "render_size")
        self.view = view
        self.agent_reward = agent_reward
        self.render_mode = render_mode
        slots = self.episodes.sizes[0]
        self.possible_agents = [f"camera_{j}" for j in range(slots)]
        self.agents = []
        # The team view ends with the agent's id, one-hot over the camera slots.
        self._ids = np.eye(slots, dtype=np.float32)
        # One space object per agent, every call (PettingZoo seeds spaces through them).
        self.observation_spaces = {
            a: _observation_space(self.episodes, slots if view == "team" else 0)
            for a in self.possible_agents}
        low, high = self.episodes.action_bounds()
        self.action_spaces = {a: spaces.Box(low[j], high[j], dtype=self.episodes.action_dtype)
                              for j, a in enumerate(self.possible_agents)}
        self.state_space = _observation_space(self.episodes)
        self._rng = np.random.default_rng()

    def observation_space(self, agent):
        """The Box of an agent's observations."""
        return self.observation_spaces[agent]

    def action_space(self, agent):
        """The Box of an agent's commands: vx, vy, yaw rate (normalized, or m/s and rad/s)."""
        return self.action_spaces[agent]

    def _observations(self):
        episodes, cameras = self.episodes, self.episodes.cameras()
        observations = {}
        for j, agent in enumerate(self.agents):
            if j >= cameras:  # a slot this scene has no camera for: nothing to observe
                observations[agent] = np.zeros(self.observation_spaces[agent].shape, np.float32)
            elif self.view == "team":
                observations[agent] = np.concatenate([episodes.observation(), self._ids[j]])
            else:
                observations[agent] = episodes.observation(self.view, j)
        return observations

    def _rewards(self, terms):
        episode, cameras = self.episodes.episode, self.episodes.cameras()
        team = self.episodes.reward(terms)
        return {agent: (0.0 if j >= cameras else team if self.agent_reward == "team"
                        else self.episodes.reward(episode.own_terms(j)))
                for j, agent in enumerate(self.agents)}

    @one_call_at_a_time
    def reset(self, seed=None, options=None):
        """Starts an episode at t = 0: (observations, infos), one entry per agent. Every
        possible agent starts; one whose slot the scene has no camera for (a family's smaller
        team) observes zeros and is terminated at the first step."""
        if seed is not None:
            self._rng = np.random.default_rng(seed)
        self.episodes.start(self._rng, options)
        self.agents = list(self.possible_agents)
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
        cameras = self.episodes.cameras()
        commands = np.zeros((cameras, 3))
        scale = self.episodes.action_scale
        for j, agent in enumerate(self.agents[:cameras]):
            if agent in actions:
                commands[j] = commands_of(actions[agent], scale[j], (3,), f"actions[{agent!r}]")
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
        self.agents = [] if over else agents[:cameras]
        return (observations, rewards, {a: j >= cameras for j, a in enumerate(agents)},
                {a: over for a in agents}, {a: dict(info) for a in agents})

    def state(self):
        """The team's observation now (the layout of docs/python.md)."""
        return self.episodes.observation()

    def render(self):
        """The present instant as camcov render draws it, (height, width, 3) uint8 RGB, for
        render_mode "rgb_array"; None otherwise."""
        if self.render_mode != "rgb_array" or self.episodes.episode is None:
            return None
        return self.episodes.episode.frame(*self.render_size)

    def close(self):
        """Nothing to release: episodes free themselves."""
