"""What Python costs over C++ (issue: a Python controller step at most 2x the same controller
in C++ on dynamic9; visibility of 1,000 random poses from Python within 1.2x of C++).

Usage: python3 tests/bench/python_parity.py [BUILD_DIR] [--repetitions N]
with the published scenes at COVERAGE_SCENES_DIR (default ../shared/coverage_scenes).
 - Visibility: BUILD_DIR/tests/bench/bench_python_parity times 1,000 random poses in C++; this
   script times the same poses (the same splitmix64 draws) from Python.
 - Run: a 30 s dynamic9 run of the nearest-unseen example, in Python (examples/
   nearest_unseen.py through camcov.simulate) and in C++ (camcov.run, which runs entirely in
   C++ without the GIL), taken in turns in this process. The two runs are the same run.
Prints medians over the repetitions and their ratio.
"""
import argparse
import json
import math
import os
import pathlib
import statistics
import subprocess
import sys
import time

repo = pathlib.Path(__file__).resolve().parents[2]
parser = argparse.ArgumentParser()
parser.add_argument("build", nargs="?", default=str(repo / "build"))
parser.add_argument("--repetitions", type=int, default=7)
args = parser.parse_args()
build = pathlib.Path(args.build)
sys.path[:0] = [str(build / "python"), str(repo / "examples")]

import camcov  # noqa: E402
import numpy as np  # noqa: E402
from nearest_unseen import NearestUnseen  # noqa: E402

scenes = pathlib.Path(os.environ.get("COVERAGE_SCENES_DIR", repo.parent / "shared/coverage_scenes"))
scene_file = str(scenes / "dynamic9.json")


def splitmix64_poses(boundary, count, seed=1):
    """bench_python_parity.cpp's poses: splitmix64, uniform over the box and the yaw circle."""
    state, mask = seed, (1 << 64) - 1

    def uniform(lo, hi):
        nonlocal state
        state = (state + 0x9E3779B97F4A7C15) & mask
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & mask
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & mask
        return lo + (hi - lo) * float((z ^ (z >> 31)) >> 11) * 2.0**-53

    (x0, y0), (x1, y1) = boundary.min(axis=0), boundary.max(axis=0)
    poses = []
    for _ in range(count):
        x = uniform(x0, x1)
        y = uniform(y0, y1)
        poses.append((x, y, uniform(-math.pi, math.pi)))
    return np.array(poses)


def median_seconds(work):
    times = []
    for _ in range(args.repetitions):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def cpp_rows():
    out = subprocess.run([str(build / "tests/bench/bench_python_parity"),
                          "--benchmark_format=json",
                          f"--benchmark_repetitions={args.repetitions}",
                          "--benchmark_report_aggregates_only=true"],
                         check=True, capture_output=True, text=True).stdout
    rows = {}
    for b in json.loads(out)["benchmarks"]:
        if b.get("aggregate_name") == "median":
            unit = {"us": 1e-6, "ms": 1e-3, "ns": 1e-9}[b["time_unit"]]
            rows[b["run_name"]] = b["real_time"] * unit
    return rows


scene = camcov.load_scene(scene_file)
world = scene.world_at(0.0)
visibility = camcov.Visibility(world, scene.half_fovs)
poses = splitmix64_poses(world.boundary, 1000)
one_by_one = [p[None, :] for p in poses]
def run_pair():
    """Median seconds of the Python and the C++ run, taken in turns."""
    python, cpp = [], []
    for _ in range(args.repetitions):
        for times, run in ((python, lambda: camcov.simulate(scene_file, NearestUnseen(scene),
                                                            method="nearest-unseen-py")),
                           (cpp, lambda: camcov.run(scene_file, method="nearest-unseen"))):
            start = time.perf_counter()
            run()
            times.append(time.perf_counter() - start)
    return statistics.median(python), statistics.median(cpp)


python = {
    "Visibility/Segments": median_seconds(lambda: visibility.segments_each(poses)),
    "Visibility/Terms": median_seconds(lambda: visibility.terms_each(poses)),
    "Visibility/Segments one call per pose":
        median_seconds(lambda: [visibility.segments(p) for p in one_by_one]),
    "Visibility/Terms one call per pose":
        median_seconds(lambda: [visibility.terms(p) for p in one_by_one]),
}
cpp = cpp_rows()
python["Run/nearest-unseen"], cpp["Run/nearest-unseen"] = run_pair()
print(f"{'work (dynamic9)':<40} {'C++':>10} {'Python':>10} {'ratio':>6}")
for name, seconds in python.items():
    reference = cpp[name.replace(" one call per pose", "")]
    print(f"{name:<40} {reference * 1e3:>8.2f}ms {seconds * 1e3:>8.2f}ms {seconds / reference:>6.2f}")
