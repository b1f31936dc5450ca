"""camcov.env.CoverageEnv: a Gymnasium environment (imported by camcov.env on first use)."""
import gymnasium
import numpy as np
from gymnasium import spaces

from camcov.env import Episodes, commands_of, one_call_at_a_time


def _action_space(episodes):
    """Each camera slot's vx, vy and yaw rate: normalized, float32 in [-1, 1] (1 is the running
    scene's camera's own limit), or in m/s and rad/s within the largest limits of any scene's
    camera in that slot. The simulator saturates ‖(vx, vy)‖ to the camera's v_max and the yaw
    rate to its γ̇_max (constraint 3)."""
    low, high = episodes.action_bounds()
    return spaces.Box(low=low, high=high, dtype=episodes.action_dtype)


def _observation_space(episodes, extra=0):
    """The Box of a vector observation, within the encoding's bounds; `extra` floats in
    [0, 1] appended (an agent's id)."""
    low, high = episodes.observation_bounds()
    if extra:
        low = np.concatenate([low, np.zeros(extra, np.float32)])
        high = np.concatenate([high, np.ones(extra, np.float32)])
    return spaces.Box(low=low, high=high, dtype=np.float32)


def _image_size(size, what):
    if (not isinstance(size, (tuple, list)) or len(size) != 2 or
            not all(isinstance(v, int) and 16 <= v <= 8192 for v in size)):
        raise ValueError(f"{what}: expected (width, height) in pixels, each 16 to 8192, "
                         f"got {size!r}")
    return tuple(size)


class CoverageEnv(gymnasium.Env):
    """camcov's simulator as a Gymnasium environment: one action moves the whole team.

    CoverageEnv(scene, params=None, reward="reward", observation="vector",
                image_size=(84, 84), render_mode=None, render_size=(640, 480),
                action_units="normalized", targets=None, pad_to=None)

    - scene: a scene file, a camcov.Scene, or a list of them (camcov.env.family(...)); reset()
      picks one with its seeded generator, or options={"scene": i}.
    - params: parameter overrides as camcov.parameters takes them ({"sim.duration": 10}); the
      episode lasts sim.duration (truncation), in steps of sim.dt; the safety layer stays on.
    - reward: "reward" (eq. 8, λ1·coverage + λ2·utilization − λ3·repulsion) or "coverage"
      (eq. 3, as the reward takes it: weighted where the scene has importance weights), of the
      team at the instant the step reaches.
    - observation: "vector" (float32, the fixed layout of docs/python.md, padded to the
      largest scene, within its declared bounds) or "image" (the frame camcov render draws,
      image_size, uint8 RGB).
    - action: (cameras, 3): vx, vy, yaw rate per camera slot; action_units "normalized"
      (float32 in [-1, 1], times the running scene's camera's limits: 1 is its v_max or
      γ̇_max) or "physical" (float64, m/s and rad/s). Rows of slots a scene has no camera
      for are not read. NaN, infinities or another shape raise.
    - targets: None (target slot i is the scene's target i) or k: the k targets present
      nearest the cameras, nearest first (a fixed size for crowds whose people come and go).
    - pad_to: {"cameras": c, "obstacles": o, "vertices": v}, any of them: pad to more than
      the scenes need, so that scenes of different sizes share one observation shape.
    - render_mode "rgb_array": render() returns the frame, (height, width, 3) uint8.
    info (the same keys in every environment of camcov.env): time, scene, seed (the run seed
    policy() uses), the team's terms now, and at the end the run's summary and its
    average_coverage (eq. 4).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}

    def __init__(self, scene, params=None, reward="reward", observation="vector",
                 image_size=(84, 84), render_mode=None, render_size=(640, 480),
                 action_units="normalized", targets=None, pad_to=None):
        """The environment of the scenes, with the options of the class's docstring."""
        super().__init__()
        self.episodes = Episodes(scene, params, reward, action_units, targets, pad_to)
        if observation not in ("vector", "image"):
            raise ValueError(f"observation: expected 'vector' or 'image', got {observation!r}")
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: expected None or 'rgb_array', got {render_mode!r}")
        self.observation_kind = observation
        self.image_size = _image_size(image_size, "image_size")
        self.render_size = _image_size(render_size, "render_size")
        self.render_mode = render_mode
        self.action_space = _action_space(self.episodes)
        if observation == "vector":
            self.observation_space = _observation_space(self.episodes)
        else:
            width, height = self.image_size
            self.observation_space = spaces.Box(0, 255, (height, width, 3), np.uint8)

    def _observation(self):
        episode = self.episodes.episode
        if self.observation_kind == "image":
            return episode.frame(*self.image_size)
        return self.episodes.observation()

    @one_call_at_a_time
    def reset(self, *, seed=None, options=None):
        """Starts an episode at t = 0: (observation, info)."""
        super().reset(seed=seed)
        self.episodes.start(self.np_random, options)
        return self._observation(), self.episodes.info()

    @one_call_at_a_time
    def step(self, action):
        """Moves every camera by its command for one step of sim.dt: (observation, reward,
        terminated (always False: coverage has no goal state), truncated (at sim.duration),
        info)."""
        episodes = self.episodes
        if episodes.episode is None:
            raise RuntimeError("step: call reset() first")
        if episodes.episode.finished:
            raise RuntimeError("step: the episode is over; call reset()")
        episodes.episode.step(commands_of(action, episodes.action_scale,
                                          self.action_space.shape, "action"))
        observation = self._observation()
        terms = episodes.episode.terms
        truncated = episodes.episode.finished
        return observation, episodes.reward(terms), False, truncated, episodes.info(terms)

    def render(self):
        """The present instant as camcov render draws it, (height, width, 3) uint8 RGB, for
        render_mode "rgb_array"; None otherwise."""
        if self.render_mode != "rgb_array" or self.episodes.episode is None:
            return None
        return self.episodes.episode.frame(*self.render_size)
