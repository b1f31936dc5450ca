"""camcov.env.CoverageEnv: a Gymnasium environment (imported by camcov.env on first use)."""
import gymnasium
import numpy as np
from gymnasium import spaces

from camcov.env import Episodes, one_call_at_a_time


def _action_space(episodes):
    """Each camera slot's vx, vy (m/s) and yaw rate (rad/s) within the largest limits of any
    scene's camera in that slot; the simulator saturates ‖(vx, vy)‖ to the camera's own
    v_max and the yaw rate to its own γ̇_max (constraint 3)."""
    return spaces.Box(low=-episodes.limits, high=episodes.limits, dtype=np.float64)


def _image_size(size, what):
    if (not isinstance(size, (tuple, list)) or len(size) != 2 or
            not all(isinstance(v, int) and 16 <= v <= 8192 for v in size)):
        raise ValueError(f"{what}: expected (width, height) in pixels, each 16 to 8192, "
                         f"got {size!r}")
    return tuple(size)


class CoverageEnv(gymnasium.Env):
    """camcov's simulator as a Gymnasium environment: one action moves the whole team.

    CoverageEnv(scene, params=None, reward="reward", observation="vector",
                image_size=(84, 84), render_mode=None, render_size=(640, 480))

    - scene: a scene file, a camcov.Scene, or a list of them (camcov.env.family(...)); reset()
      picks one with its seeded generator, or options={"scene": i}.
    - params: parameter overrides as camcov.parameters takes them ({"sim.duration": 10}); the
      episode lasts sim.duration (truncation), in steps of sim.dt; the safety layer stays on.
    - reward: "reward" (eq. 8, λ1·coverage + λ2·utilization − λ3·repulsion) or "coverage"
      (eq. 3, as the reward takes it: weighted where the scene has importance weights), of the
      team at the instant the step reaches.
    - observation: "vector" (float32, the fixed layout of docs/python.md, padded to the
      largest scene) or "image" (the frame camcov render draws, image_size, uint8 RGB).
    - action: (cameras, 3) float64: vx, vy (m/s), yaw rate (rad/s) per camera slot; rows of
      slots a scene has no camera for are not read. NaN, infinities or another shape raise.
    - render_mode "rgb_array": render() returns the frame, (height, width, 3) uint8.
    info: time, scene, seed (the run seed policy() uses), the team's terms now, and at the
    end the run's summary (its average coverage, eq. 4).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 10}

    def __init__(self, scene, params=None, reward="reward", observation="vector",
                 image_size=(84, 84), render_mode=None, render_size=(640, 480)):
        """The environment of the scenes, with the options of the class's docstring."""
        super().__init__()
        self.episodes = Episodes(scene, params, reward)
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
            self.observation_space = spaces.Box(-np.inf, np.inf,
                                                (self.episodes.observation_size,), np.float32)
        else:
            width, height = self.image_size
            self.observation_space = spaces.Box(0, 255, (height, width, 3), np.uint8)

    def _observation(self):
        episode = self.episodes.episode
        if self.observation_kind == "image":
            return episode.frame(*self.image_size)
        return episode.observation(self.episodes.sizes)

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
        action = np.asarray(action, dtype=np.float64)
        if action.shape != self.action_space.shape:
            raise ValueError(f"action: expected shape {self.action_space.shape} (vx, vy, yaw "
                             f"rate per camera), got {action.shape}")
        episodes.episode.step(action)
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
