#!/usr/bin/env python3
"""How the offline optimum grows with its budget (docs/method.md, "The offline optimum"): for
each `camcov optimum -o` file, the best reward found within each budget (read from the file's
curve), and the coverage of the pose it ends with. Files of the same scene searched from
other seeds show whether restarts agree.

    for s in 1 2; do for i in $(seq 1 16); do
      camcov optimum ../shared/coverage_scenes/static$i.json --budget 2000000 --seed $s \
          -o optimum/static$i-seed$s.json
    done; done
    scripts/optimum_curve.py optimum/*.json
"""
import json
import re
import sys
from pathlib import Path

BUDGETS = [1_000, 10_000, 50_000, 200_000, 1_000_000, 2_000_000]


def natural(path):
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", Path(path).stem)]


def best_within(curve, budget):
    best = None
    for step in curve:  # in order of evaluations, each better than the last
        if step["evaluations"] <= budget:
            best = step["reward"]
    return best


def main(files):
    print("| file | " + " | ".join(f"reward ≤ {b:,}" for b in BUDGETS) +
          " | coverage of the best | found after |")
    print("|---" * (len(BUDGETS) + 3) + "|")
    for f in sorted(files, key=natural):
        o = json.loads(Path(f).read_text())
        cells = []
        for b in BUDGETS:
            v = best_within(o["curve"], b) if b <= o["budget"] else None
            cells.append("—" if v is None else f"{v:.4f}")
        print(f"| {Path(f).stem} | " + " | ".join(cells) +
              f" | {o['best']['coverage']:.4f} | {o['found']['evaluations']:,} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
