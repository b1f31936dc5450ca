"""Steps per second of camcov's learning environments (camcov.env), against the simulator alone.

    PYTHONPATH=build/python:../shared/vendor/python python3 tests/bench/env_speed.py \
        [SCENE] [--seconds S] [--envs N]

On the scene (default: the published dynamic9, five cameras, six targets), with random
actions within the cameras' limits, prints the median of three timings of:
  - the simulator alone: camcov.Episode.step, one episode, no Gymnasium around it;
  - CoverageEnv.step: one Gymnasium environment on one core;
  - VectorCoverageEnv.step: N environments stepped in C++ threads, on 1 thread and on 2.
A benchmark, not a test: the figures depend on the machine (docs/python.md quotes them).
"""
import argparse
import os
import statistics
import time

import numpy as np

import camcov
import camcov.env


def rate(step, seconds, per_call=1):
    """Calls step() for `seconds`; steps per second."""
    calls, start = 0, time.perf_counter()
    while time.perf_counter() - start < seconds:
        step()
        calls += 1
    return calls * per_call / (time.perf_counter() - start)


def simulator_alone(scene, rng):
    episode = [camcov.Episode(scene)]
    limits = camcov.env.Episodes(scene).limits

    def step():
        if episode[0].finished:
            episode[0] = camcov.Episode(scene)
        episode[0].step(rng.uniform(-limits, limits))
    return step


def one_environment(scene):
    env = camcov.env.CoverageEnv(scene)
    env.reset(seed=1)
    env.action_space.seed(1)

    def step():
        if env.step(env.action_space.sample())[3]:
            env.reset()
    return step


def vector(scene, envs, threads):
    env = camcov.env.VectorCoverageEnv(scene, envs, threads=threads)
    env.reset(seed=1)
    env.action_space.seed(1)
    return lambda: env.step(env.action_space.sample())


def main():
    default = os.path.join(os.environ.get("COVERAGE_SCENES_DIR", "../shared/coverage_scenes"),
                           "dynamic9.json")
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene", nargs="?", default=default)
    parser.add_argument("--seconds", type=float, default=2.0, help="per timing")
    parser.add_argument("--envs", type=int, default=8, help="environments of the vector form")
    args = parser.parse_args()
    scene = camcov.load_scene(args.scene)
    rng = np.random.default_rng(1)
    cases = [("simulator alone (camcov.Episode.step)", simulator_alone(scene, rng), 1),
             ("CoverageEnv, one environment", one_environment(scene), 1)]
    for threads in (1, 2):
        cases.append((f"VectorCoverageEnv, {args.envs} environments, {threads} thread"
                      f"{'s' if threads > 1 else ''}", vector(scene, args.envs, threads),
                      args.envs))
    print(f"{scene.name}: environment steps per second (median of 3 timings of "
          f"{args.seconds:g} s)")
    for name, step, per_call in cases:
        figure = statistics.median(rate(step, args.seconds, per_call) for _ in range(3))
        print(f"  {name:55s} {figure:10,.0f}")


if __name__ == "__main__":
    main()
