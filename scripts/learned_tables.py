#!/usr/bin/env python3
"""The tables of docs/method.md ("Learned method") from batch folders run on the same scenes
(their summary.csv files, read together: the learned method and the baseline in one batch,
the paper's method and ours in another): per family or folder, each method's mean average
coverage and on how many scenes the learned method's mean is above, equal to or below each
other method's; then the scenes where it is below the baseline.

    camcov bench --scenes test --methods learned,local --seeds 4 ... --out test-learned
    camcov bench --scenes test --methods paper,camcov --seeds 4 ... --out test-paper
    scripts/learned_tables.py test-learned test-paper
"""
import csv
import json
import sys
from collections import defaultdict
from pathlib import Path

LEARNED, ORDER = "learned", ("learned", "local", "paper", "camcov")


def main(folders):
    mean, group = {}, {}
    for folder in map(Path, folders):
        for row in csv.DictReader(open(folder / "summary.csv")):
            mean[row["scene"], row["method"]] = float(row["coverage_mean"])
        for g in json.loads((folder / "summary.json").read_text())["groups"]:
            group.update({scene: g["name"] for scene in g["scenes"]})
    methods = [m for m in ORDER if any(k[1] == m for k in mean)]
    scenes = sorted({scene for scene, _ in mean})
    others = [m for m in methods if m != LEARNED]
    rows = defaultdict(list)
    for scene in scenes:
        rows[group.get(scene, "all")].append(scene)
    print("| family | scenes | " + " | ".join(methods) + " | " +
          " | ".join(f"learned vs {m} (above/equal/below)" for m in others) + " |")
    print("|---" * (2 + len(methods) + len(others)) + "|")
    for name in sorted(rows) + ["all"]:
        members = scenes if name == "all" else rows[name]
        cells = [f"{sum(mean[s, m] for s in members) / len(members):.3f}" for m in methods]
        verdicts = []
        for m in others:
            d = [mean[s, LEARNED] - mean[s, m] for s in members]
            verdicts.append(f"{sum(x > 1e-9 for x in d)}/{sum(abs(x) <= 1e-9 for x in d)}/"
                            f"{sum(x < -1e-9 for x in d)}")
        label = f"**{name}**" if name == "all" else name
        print(f"| {label} | {len(members)} | " + " | ".join(cells + verdicts) + " |")
    if "local" in methods:
        below = [s for s in scenes if mean[s, LEARNED] < mean[s, "local"] - 1e-9]
        print("\nbelow the baseline: " + (", ".join(
            f"{s} ({mean[s, LEARNED]:.3f} vs {mean[s, 'local']:.3f})" for s in below) or "none"))


if __name__ == "__main__":
    main(sys.argv[1:])
