#!/usr/bin/env python3
"""Trains the learned method's policy (camcov run --method learned) and writes its weights.

    PYTHONPATH=build/python /usr/bin/python3 scripts/train_learned.py \
        --out src/control/learned_policy.json --curve docs/learned_training.png

The choice: one policy whose parameters every camera shares, trained by PPO (independent
learners with shared parameters, the simplest member of the MAPPO family), a small MLP on the
camera's own observation.

- Shared parameters: teams have 1 to 8 cameras and every camera is the same kind of agent
  (its limits are in its observation, its action is normalized by them), so one policy serves
  any team size, sees every camera's experience (eight times the data of a camera of its own)
  and is what the C++ method runs for each camera in turn.
- The own view (camcov.env's CoverageParallelEnv(view="own", targets=K)): the camera's slot
  first, its teammates after it, the K nearest targets it sees some of. "Me" is always slot 0,
  so the network needs no agent id to know which camera it drives, and the input has one size
  whatever the scene. The own view leaves obstacle slots zero, so the policy's sizes have none
  (SIZES): its observation is the parallel environment's own view without those zeros, made by
  the same C++ encoding (control/observation_encoding.h) the C++ method calls.
- PPO: on-policy, stable with a fixed set of hyperparameters, and cheap per sample: what a
  quarter of an hour on two shared cores can afford. Its critic reads the same observation as
  the actor (which carries the team's coverage and the teammates): a central critic over the
  team's state would need the largest team's padding for little gain at this budget.
- A small MLP (two hidden layers of 64, tanh): a forward pass in C++ costs a few microseconds
  per camera, so the method runs far faster than real time.

The reward of each camera is the team's coverage at the next instant (eq. (3), what the
benchmark averages) plus half the camera's own coverage term (the share of the targets'
boundary it sees itself), which tells each camera what it contributed. Episodes are the
scenes of every generated family's tune seeds (docs/families.md), 30 s each; the test seeds are
never seen. Everything is seeded (torch.manual_seed, numpy's generator, the run seeds), torch
runs on one thread, so the same command writes the same weights on the same machine.

The JSON holds the observation it expects (view, target slots, sizes, the running mean and
deviation it normalizes by, the clip) and the actor's layers; CMake embeds it into camcov.
"""
import argparse
import json
import pathlib
import sys
import time

import numpy as np
import torch
from torch import nn

import camcov
import camcov.env

# cameras, targets (nearest first), obstacles (the own view shows none), vertices a ring:
# every generated family and published scene fits (big_teams has 8 cameras; rings have at most
# 9 vertices).
SIZES = (8, 4, 0, 12)
VIEW, TARGETS = "own", "nearest"
OBSERVATION_SIZE = len(camcov.observation_bounds(SIZES)[0])
# The own view's first camera slot, after the 4 global floats: its own coverage term.
OWN_COVERAGE = 4 + camcov.camera_columns().index("coverage")
TEAM_COVERAGE = 1
OWN_WEIGHT = 0.5
CLIP = 10.0
HIDDEN = 64


def observe(episode, camera):
    """Camera `camera`'s observation of the episode's present instant, as the policy reads it."""
    return episode.observation(SIZES, VIEW, camera, TARGETS)


def limits_of(scene):
    """(M, 3): what a normalized action's vx, vy and yaw rate are multiplied by (camcov.env)."""
    return np.array([[c["maxVelocity"], c["maxVelocity"], c["maxAngularVelocity"]]
                     for c in scene.cameras])


def mlp(outputs):
    """The network both actor and critic are: two tanh layers of HIDDEN, then linear."""
    return nn.Sequential(nn.Linear(OBSERVATION_SIZE, HIDDEN), nn.Tanh(),
                         nn.Linear(HIDDEN, HIDDEN), nn.Tanh(), nn.Linear(HIDDEN, outputs))


class RunningNormal:
    """The observation's running mean and variance (Chan et al.'s parallel update)."""

    def __init__(self):
        self.mean = np.zeros(OBSERVATION_SIZE)
        self.var = np.ones(OBSERVATION_SIZE)
        self.count = 1e-4

    def update(self, rows):
        mean, var, n = rows.mean(0), rows.var(0), len(rows)
        delta, total = mean - self.mean, self.count + n
        self.mean = self.mean + delta * n / total
        self.var = (self.var * self.count + var * n + delta**2 * self.count * n / total) / total
        self.count = total

    def std(self):
        """The deviation divided by; a feature that never varied (padding) is divided by 1."""
        std = np.sqrt(self.var + 1e-8)
        return np.where(std < 1e-6, 1.0, std)

    def __call__(self, rows):
        return np.clip((rows - self.mean) / self.std(), -CLIP, CLIP)


class Policy(nn.Module):
    """The shared actor (a Gaussian around its mean) and critic."""

    def __init__(self):
        super().__init__()
        self.actor, self.critic = mlp(3), mlp(1)
        self.log_std = nn.Parameter(torch.full((3,), -0.5))
        with torch.no_grad():  # small first actions: a camera starts by barely moving
            self.actor[-1].weight.mul_(0.01)
            self.actor[-1].bias.zero_()


def scene_pool(per_family):
    """The first `per_family` scenes of every generated family's tune seeds."""
    return [s for name in camcov.families() for s in camcov.env.family(name, "tune", per_family)]


def observations(episode, cameras):
    """(cameras, OBSERVATION_SIZE): every camera's observation of the present instant."""
    return np.stack([observe(episode, j) for j in range(cameras)])


def mean_action(actor, normal, rows):
    """The deterministic action the C++ method proposes: the mean, clipped to [-1, 1]."""
    with torch.no_grad():
        x = torch.as_tensor(normal(rows), dtype=torch.float32)
        return np.clip(actor(x).numpy().astype(np.float64), -1.0, 1.0)


def run_episode(scene, choose, params=None):
    """One episode's average coverage (eq. (4)) with actions choose(observations) -> (M, 3)."""
    episode = camcov.Episode(scene, params)
    limits = limits_of(scene)
    while not episode.finished:
        episode.step(choose(observations(episode, len(limits))) * limits)
    episode.close()
    return episode.summary["averageCoverage"]


def train(scenes, steps, seed=1, envs=16, horizon=128, log=print):
    """PPO on `scenes` for `steps` team steps: (actor, normal, curve), the curve a list of
    (team steps so far, mean average coverage of the episodes finished since the last point)."""
    torch.manual_seed(seed)
    torch.set_num_threads(1)
    rng = np.random.default_rng(seed)
    policy = Policy()
    optimizer = torch.optim.Adam(policy.parameters(), lr=3e-4, eps=1e-5)
    normal = RunningNormal()
    gamma, lam, clip, epochs, minibatch = 0.99, 0.95, 0.2, 4, 1024

    def start():
        """A new episode of a scene drawn from the pool: (episode, limits, observations)."""
        scene = scenes[int(rng.integers(len(scenes)))]
        episode = camcov.Episode(scene)
        return episode, limits_of(scene), observations(episode, len(scene.cameras))

    def segments(limits):
        """A fresh series per camera: observation, action, log-probability, value, reward."""
        return [{"obs": [], "act": [], "logp": [], "val": [], "rew": []} for _ in limits]

    running = [start() for _ in range(envs)]
    done, curve, finished = 0, [], []
    while done < steps:
        # The step size falls linearly to zero over the training: large steps first, fine
        # adjustments of the mean (the action the method takes) at the end.
        for g in optimizer.param_groups:
            g["lr"] = 3e-4 * (1.0 - done / steps)
        live = [segments(limits) for _, limits, _ in running]
        ended = []  # the series of episodes that finished during this rollout: terminal
        for _ in range(horizon):
            raw = np.concatenate([seen for _, _, seen in running])
            normal.update(raw)
            rows = torch.as_tensor(normal(raw), dtype=torch.float32)
            with torch.no_grad():
                mean, value = policy.actor(rows), policy.critic(rows)[:, 0]
                dist = torch.distributions.Normal(mean, policy.log_std.exp())
                action = dist.sample()
                logp = dist.log_prob(action).sum(-1)
            at = 0
            for i, (episode, limits, _) in enumerate(running):
                m = len(limits)
                a = action[at:at + m].numpy().astype(np.float64)
                episode.step(np.clip(a, -1.0, 1.0) * limits)
                seen = observations(episode, m)
                running[i] = (episode, limits, seen)
                for j, s in enumerate(live[i]):
                    s["obs"].append(rows[at + j])
                    s["act"].append(action[at + j])
                    s["logp"].append(logp[at + j])
                    s["val"].append(float(value[at + j]))
                    s["rew"].append(
                        float(seen[j, TEAM_COVERAGE] + OWN_WEIGHT * seen[j, OWN_COVERAGE]))
                at += m
                if episode.finished:
                    episode.close()
                    finished.append(episode.summary["averageCoverage"])
                    ended += [(s, 0.0) for s in live[i]]
                    running[i] = start()
                    live[i] = segments(running[i][1])
            done += len(running)
        # The series still running are bootstrapped by the critic's value of where they stand.
        for (_, _, seen), cameras in zip(running, live):
            with torch.no_grad():
                tail = policy.critic(torch.as_tensor(normal(seen), dtype=torch.float32))[:, 0]
            ended += [(s, float(v)) for s, v in zip(cameras, tail)]
        # Advantages by GAE; an episode's end is terminal (the observation holds t / duration).
        batch = {"obs": [], "act": [], "logp": [], "adv": [], "ret": []}
        for s, bootstrap in ended:
            if not s["rew"]:
                continue
            advantage, next_value, running_advantage = [0.0] * len(s["rew"]), bootstrap, 0.0
            for t in reversed(range(len(s["rew"]))):
                delta = s["rew"][t] + gamma * next_value - s["val"][t]
                running_advantage = delta + gamma * lam * running_advantage
                advantage[t], next_value = running_advantage, s["val"][t]
            batch["obs"] += s["obs"]
            batch["act"] += s["act"]
            batch["logp"] += s["logp"]
            batch["adv"] += advantage
            batch["ret"] += [a + v for a, v in zip(advantage, s["val"])]
        obs, act = torch.stack(batch["obs"]), torch.stack(batch["act"])
        old_logp = torch.stack(batch["logp"])
        adv = torch.as_tensor(batch["adv"], dtype=torch.float32)
        ret = torch.as_tensor(batch["ret"], dtype=torch.float32)
        adv = (adv - adv.mean()) / (adv.std() + 1e-8)
        for _ in range(epochs):
            order = torch.randperm(len(obs))
            for begin in range(0, len(obs), minibatch):
                pick = order[begin:begin + minibatch]
                dist = torch.distributions.Normal(policy.actor(obs[pick]), policy.log_std.exp())
                ratio = (dist.log_prob(act[pick]).sum(-1) - old_logp[pick]).exp()
                surrogate = torch.min(ratio * adv[pick],
                                      ratio.clamp(1 - clip, 1 + clip) * adv[pick])
                value_loss = (policy.critic(obs[pick])[:, 0] - ret[pick]).pow(2).mean()
                loss = -surrogate.mean() + 0.5 * value_loss
                optimizer.zero_grad()
                loss.backward()
                nn.utils.clip_grad_norm_(policy.parameters(), 0.5)
                optimizer.step()
        if finished:
            curve.append((done, float(np.mean(finished))))
            log(f"{done:>9} team steps: mean average coverage {curve[-1][1]:.3f} "
                f"({len(finished)} episodes)")
            finished = []
    return policy.actor, normal, curve


def short(values):
    """Numbers as float32 holds them, written with the 9 digits that keep every bit."""
    return [float(f"{v:.9g}") for v in np.asarray(values, dtype=np.float32).ravel()]


def export(actor, normal, path, about):
    """Writes the policy's JSON: the observation it expects and the actor's layers."""
    layers = [m for m in actor if isinstance(m, nn.Linear)]
    policy = {
        "about": about,
        "observation": {"view": VIEW, "targets": TARGETS, "sizes": list(SIZES),
                        "mean": short(normal.mean), "std": short(normal.std()), "clip": CLIP},
        "layers": [{"weight": [short(row) for row in layer.weight.detach().numpy()],
                    "bias": short(layer.bias.detach().numpy())} for layer in layers],
    }
    pathlib.Path(path).write_text(json.dumps(policy, separators=(",", ":")) + "\n")


def plot(curve, path, title):
    """The training curve as a PNG."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axes = plt.subplots(figsize=(6, 3.5), dpi=100)
    steps, coverage = zip(*curve)
    axes.plot(np.array(steps) / 1e6, coverage, color="#8c564b")
    axes.set_xlabel("team steps (millions)")
    axes.set_ylabel("mean average coverage")
    axes.set_title(title, fontsize=9)
    axes.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(path, metadata={"Software": None})


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--steps", type=int, default=800_000, help="team steps of training")
    parser.add_argument("--per-family", type=int, default=50,
                        help="tune scenes of each family to train on")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default="src/control/learned_policy.json")
    parser.add_argument("--curve", default="docs/learned_training.png")
    args = parser.parse_args()
    began = time.monotonic()
    actor, normal, curve = train(scene_pool(args.per_family), args.steps, args.seed,
                                 log=lambda line: print(line, flush=True))
    minutes = (time.monotonic() - began) / 60
    command = (f"scripts/train_learned.py --steps {args.steps} --per-family "
               f"{args.per_family} --seed {args.seed}")
    export(actor, normal, args.out, command)
    plot(curve, args.curve, f"{command} ({minutes:.0f} min)")
    print(f"wrote {args.out} and {args.curve} in {minutes:.1f} min", file=sys.stderr)


if __name__ == "__main__":
    main()
