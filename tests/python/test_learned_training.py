"""The learned method: its training learns (a short run beats a random policy), and the weights
it exports act in C++ (the network `--method learned` proposes steps with) as in torch, to
1e-6, on the observation the parallel environment's own view gives.

scripts/train_learned.py is imported from the source tree; torch is Debian's python3-torch.
Gymnasium and PettingZoo's sources are in ../shared/vendor/python (as in test_env.py).
"""
import json
import os
import pathlib
import sys

import numpy as np
import pytest
import torch

import camcov

REPO = pathlib.Path(__file__).resolve().parents[2]
VENDOR = pathlib.Path(os.environ.get("CAMCOV_VENDOR_PYTHON",
                                     REPO.parent / "shared" / "vendor" / "python"))
sys.path.insert(0, str(VENDOR))
sys.path.insert(0, str(REPO / "scripts"))

import camcov.env  # noqa: E402
import train_learned  # noqa: E402

POLICY = REPO / "src" / "control" / "learned_policy.json"


def torch_actions(policy, rows):
    """The policy's clipped mean for each row, in float64, from the JSON alone."""
    o = policy["observation"]
    x = torch.as_tensor(rows, dtype=torch.float64)
    mean = torch.tensor(o["mean"], dtype=torch.float64)
    std = torch.tensor(o["std"], dtype=torch.float64)
    x = ((x - mean) / std).clamp(-o["clip"], o["clip"])
    layers = policy["layers"]
    for k, layer in enumerate(layers):
        x = x @ torch.tensor(layer["weight"], dtype=torch.float64).T + torch.tensor(
            layer["bias"], dtype=torch.float64)
        if k + 1 < len(layers):
            x = torch.tanh(x)
    return x.clamp(-1.0, 1.0).numpy()


def test_the_exported_weights_act_in_cpp_as_in_torch(published):
    policy = json.loads(POLICY.read_text())
    sizes = tuple(policy["observation"]["sizes"])
    assert sizes == train_learned.SIZES
    scene = camcov.load_scene(published("dynamic9"))
    limits = train_learned.limits_of(scene)
    short = {"sim.duration": 5.0}
    episode = camcov.Episode(scene, short)
    learned = camcov.MethodPolicy("learned", episode, 1)
    # The parallel environment's own view: the policy's observation followed by obstacle
    # slots the own view leaves zero.
    agents = camcov.env.make("camcov/CoverageParallel-v0", scene=scene, params=short, view="own",
                             targets=sizes[1], action_units="physical",
                             pad_to={"cameras": sizes[0], "vertices": sizes[3]})
    observed, _ = agents.reset(seed=1)
    steps = followed = 0
    while not episode.finished:
        rows = train_learned.observations(episode, len(limits))
        for j, agent in enumerate(agents.agents[:len(limits)]):
            np.testing.assert_array_equal(observed[agent][:rows.shape[1]], rows[j])
            assert not observed[agent][rows.shape[1]:].any()
        actions = camcov.learned_action(rows)
        np.testing.assert_allclose(actions, torch_actions(policy, rows), rtol=0, atol=1e-6)
        commands = learned.decide(episode)
        # The method takes a camera's proposal (scaled, saturated to ‖v‖ ≤ v_max) unless it
        # would lower the reward.
        proposed = actions * limits
        speed = np.hypot(proposed[:, 0], proposed[:, 1])
        proposed[:, :2] *= np.minimum(1.0, limits[:, :1] / np.maximum(speed, 1e-12)[:, None])
        followed += np.all(np.abs(commands - proposed) <= 1e-6, axis=1).sum()
        episode.step(commands)
        # Slots past the team (padding) are agents until the first step: they are given zeros.
        observed = agents.step({a: commands[j] if j < len(limits) else np.zeros(3)
                                for j, a in enumerate(agents.agents)})[0]
        steps += 1
    assert steps == 50
    assert followed > 0, "the method never took the network's step"
    assert np.abs(proposed).max() > 0.01, "the policy moves the cameras"
    # Rows the network cannot read are refused, never read past or turned into NaN actions.
    bad = np.array(rows[:1])
    bad[0, 3] = np.nan
    with pytest.raises(ValueError, match="learned_action: row 0 is not finite"):
        camcov.learned_action(bad)
    with pytest.raises(ValueError, match="expected observations of shape"):
        camcov.learned_action(np.zeros((1, rows.shape[1] + 1), np.float32))


def test_a_short_training_beats_a_random_policy():
    scenes = camcov.env.family("convex_rooms", "tune", 2)
    actor, normal, curve = train_learned.train(scenes, 24_000, seed=3, envs=8, horizon=100,
                                               log=lambda line: None)
    assert curve, "episodes finished during training"
    learned = [train_learned.run_episode(
        s, lambda rows: train_learned.mean_action(actor, normal, rows)) for s in scenes]
    random = []
    for seed in (1, 2, 3):
        rng = np.random.default_rng(seed)
        random += [train_learned.run_episode(
            s, lambda rows: rng.uniform(-1.0, 1.0, (len(rows), 3))) for s in scenes]
    assert np.mean(learned) > np.mean(random) + 0.02, (learned, random)
