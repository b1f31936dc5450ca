"""A random policy and the paper's method, through the Gymnasium environment (camcov.env).

    python3 examples/env_policies.py [SCENE] [--seed N]

Runs one episode of each on the scene (default: the published dynamic9) and prints their
average coverage (eq. 4). The paper's method through the environment is `camcov run --method
paper --seed N`, step for step: the last line says so. Needs gymnasium (pip install gymnasium).
"""
import argparse
import os

import numpy as np

import camcov
import camcov.env


def episode(env, act, seed):
    """Runs one episode with act(observation) -> action; returns the run's summary."""
    observation, info = env.reset(seed=seed, options={"seed": seed})
    while True:
        observation, reward, terminated, truncated, info = env.step(act(observation))
        if terminated or truncated:
            return info["summary"]


def main():
    default = os.path.join(os.environ.get("COVERAGE_SCENES_DIR", "../shared/coverage_scenes"),
                           "dynamic9.json")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", nargs="?", default=default)
    parser.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()

    env = camcov.env.CoverageEnv(args.scene)
    env.action_space.seed(args.seed)
    random = episode(env, lambda observation: env.action_space.sample(), args.seed)
    paper = episode(env, camcov.env.policy("paper", env), args.seed)
    run = camcov.run(args.scene, "paper", args.seed)
    print(f"random policy:  average coverage {random['averageCoverage']:.4f}")
    print(f"paper's method: average coverage {paper['averageCoverage']:.4f}")
    same = paper["averageCoverage"] == run.summary["averageCoverage"]
    print(f"camcov run --method paper --seed {args.seed}: "
          f"{run.summary['averageCoverage']:.4f} ({'the same' if same else 'DIFFERENT'})")
    return 0 if same else 1


if __name__ == "__main__":
    raise SystemExit(main())
