"""Training a policy with nothing but numpy: the cross-entropy method on a linear policy.

    python3 examples/env_cross_entropy.py [SCENE] [--iterations N] [--population N] [--seed N]

The policy maps the environment's observation (camcov.env's documented vector) to the team's
commands: action = tanh(W · observation + b), normalized (the environment scales 1 to each
camera's own limit). Each iteration
draws a population of (W, b) from a Gaussian, runs one episode with each, and refits the
Gaussian to the best fifth (the elite). Printed per iteration: the elite's mean average
coverage and that of the Gaussian's mean. On tests/data/scenes/tiny_dynamic.json, whose camera
starts facing away from the target, coverage climbs from 0 within a few iterations.
"""
import argparse
import pathlib

import numpy as np

import camcov.env

TINY = pathlib.Path(__file__).resolve().parents[1] / "tests" / "data" / "scenes" / "tiny_dynamic.json"


def average_coverage(env, theta, seed):
    """One episode with the linear policy theta; its average coverage (eq. 4)."""
    size = env.observation_space.shape[0]
    cameras = env.action_space.shape[0]
    weights = theta[:3 * cameras * size].reshape(3 * cameras, size)
    bias = theta[3 * cameras * size:]
    observation, _ = env.reset(seed=seed, options={"seed": seed})
    while True:
        action = np.tanh(weights @ observation + bias).reshape(cameras, 3)
        observation, _, terminated, truncated, info = env.step(action)
        if terminated or truncated:
            return info["summary"]["averageCoverage"]


def train(env, iterations, population, seed, report=print):
    """The cross-entropy method; returns the average coverage of the mean policy before
    training and after each iteration."""
    rng = np.random.default_rng(seed)
    size = env.observation_space.shape[0]
    count = 3 * env.action_space.shape[0] * (size + 1)
    mean, spread = np.zeros(count), np.full(count, 0.5)
    elite = max(2, population // 5)
    history = [average_coverage(env, mean, seed)]
    report(f"iteration 0: mean policy {history[0]:.4f}")
    for iteration in range(1, iterations + 1):
        thetas = mean + spread * rng.standard_normal((population, count))
        scores = np.array([average_coverage(env, theta, seed) for theta in thetas])
        best = thetas[np.argsort(scores)[-elite:]]
        mean, spread = best.mean(axis=0), best.std(axis=0) + 0.02
        history.append(average_coverage(env, mean, seed))
        report(f"iteration {iteration}: elite {np.sort(scores)[-elite:].mean():.4f}, "
               f"mean policy {history[-1]:.4f}")
    return history


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", nargs="?", default=str(TINY))
    parser.add_argument("--iterations", type=int, default=8)
    parser.add_argument("--population", type=int, default=30)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--duration", type=float, default=10.0, help="seconds per episode")
    args = parser.parse_args()
    env = camcov.env.CoverageEnv(args.scene, params={"sim.duration": args.duration})
    history = train(env, args.iterations, args.population, args.seed)
    print(f"average coverage {history[0]:.4f} before training, {history[-1]:.4f} after")


if __name__ == "__main__":
    main()
