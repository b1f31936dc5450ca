"""A Python controller beside the paper's method on three published scenes, with a report.

    PYTHONPATH=build/python:examples build/python/bin/python3 examples/python_bench.py \\
        [--scenes ../shared/coverage_scenes] [--out python-bench] [--seeds 5]

Writes OUT/report.html (open it in a browser) and prints how the Python method did against
the paper's, scene by scene (Mann-Whitney U, as every camcov report computes it).
"""
import argparse
import pathlib

import camcov
from nearest_unseen import NearestUnseen

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--scenes", default="../shared/coverage_scenes")
parser.add_argument("--out", default="python-bench")
parser.add_argument("--seeds", type=int, default=5)
parser.add_argument("--duration", type=float, default=30.0, help="simulated seconds per run")
parser.add_argument("--jobs", type=int, default=2, help="worker threads")
args = parser.parse_args()

scenes = [str(pathlib.Path(args.scenes) / f"{name}.json")
          for name in ("static1", "dynamic1", "dynamic9")]
summary = camcov.bench(scenes, methods=["paper"], seeds=args.seeds, out=args.out,
                       params={"sim.duration": args.duration},
                       controllers={"nearest-unseen-py": NearestUnseen},
                       reference="paper", jobs=args.jobs)
for c in summary["comparisons"]:
    print(f"{c['scene']:<10} {c['method']} against paper: {c['winner']} (p {c['pValue']:.3g})")
print(f"report: {pathlib.Path(args.out) / 'report.html'}")
