"""The nearest-unseen example method in Python: the twin of nearest_unseen_controller.cpp.

Each camera turns toward the nearest target edge that no other camera sees and moves to a
point d2 in front of it. The arithmetic follows the C++ file operation for operation, so the
two give the same runs to the byte (tests/python/test_runs.py checks it). The search
over every piece of boundary is numpy, for all cameras at once; the few numbers per camera
after it are plain floats.
"""
import math

import numpy as np

import camcov


class NearestUnseen:
    """A controller: called with each step's camcov.Observation, returns (velocities, goals).

    The constructor is also a factory for camcov.bench: (scene, params, seed). The method
    draws no random numbers, so it ignores the seed.
    """

    def __init__(self, scene, params=None, seed=None):
        params = params or camcov.parameters()
        self.dt = params["sim"]["dt"]              # s
        self.standoff = params["reward"]["d2"]     # m in front of the edge: d2 of eq. (7)
        self.max_velocity = [c["maxVelocity"] for c in scene.cameras]
        # Column of masks: every camera's bit but row j's.
        self.others = ~np.left_shift(np.uint64(1), np.arange(len(scene.cameras),
                                                             dtype=np.uint64))[:, None]

    def __call__(self, observation):
        seen = observation.seen
        a, b = seen["a"], seen["b"]
        cameras = observation.cameras
        mid = 0.5 * (a + b)
        # Rows are cameras, columns pieces of target boundary: the pieces no camera but this
        # row's sees, and the nearest of them by midpoint (the first of equals).
        free = ((seen["visible_by"] & self.others) == 0) & (a != b).any(axis=1)
        distance = np.sqrt(np.square(cameras[:, 0:1] - mid[:, 0]) +
                           np.square(cameras[:, 1:2] - mid[:, 1]))
        nearest = np.argmin(np.where(free, distance, np.inf), axis=1).tolist()
        anything = free.any(axis=1).tolist()
        # Per camera in plain floats: a handful of numbers, where numpy would cost more.
        velocities = [(0.0, 0.0, 0.0)] * len(nearest)
        goals = [(math.nan,) * 3] * len(nearest)
        for j, (x, y, yaw) in enumerate(cameras.tolist()):
            if not anything[j]:
                continue  # everything is seen: hold still
            i = nearest[j]
            mx, my = mid[i].tolist()
            (ax, ay), (bx, by) = a[i].tolist(), b[i].tolist()
            ex, ey = bx - ax, by - ay
            length = math.sqrt(ex * ex + ey * ey)
            ox, oy = ey / length, -ex / length  # outward normal: rings are counter-clockwise
            gx, gy = mx + ox * self.standoff, my + oy * self.standoff
            goals[j] = (gx, gy, math.atan2(-oy, -ox))
            dx, dy = gx - x, gy - y
            d = math.sqrt(dx * dx + dy * dy)
            scale = min(self.max_velocity[j], d / self.dt) / d if d > 0 else 0.0
            turn = math.remainder(math.atan2(my - y, mx - x) - yaw, 2.0 * math.pi) / self.dt
            velocities[j] = (dx * scale, dy * scale, turn)
        return velocities, goals
