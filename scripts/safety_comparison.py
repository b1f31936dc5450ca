#!/usr/bin/env python3
"""Side-by-side table of two batches of the same scenes: one with the safety layer, one
without (`--set safety.enabled=false`). Per scene and method: mean average coverage and the
mean time per run closer than δ (continuous time, avoidable + unavoidable), then the totals
the safety issue asks about: runs with avoidable time below δ, the change of mean coverage
over all scenes, and whether the paper method still wins or ties where it did.

    camcov bench --scenes DIR --seeds 20 --videos none --out with
    camcov bench --scenes DIR --seeds 20 --videos none --set safety.enabled=false --out without
    scripts/safety_comparison.py with without
"""
import json
import re
import sys
from pathlib import Path


def natural(name):
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def load(folder):
    summary = json.loads((Path(folder) / "summary.json").read_text())
    methods = {(m["scene"], m["method"]): m for m in summary["methods"]}
    # The paper method against the reference (the baseline), per scene.
    winners = {c["scene"]: c["winner"] for c in summary["comparisons"] if c["method"] == "paper"}
    runs = {}
    for f in (Path(folder) / "runs").glob("*.json"):
        run = json.loads(f.read_text())
        runs[(run["scene"]["name"], run["method"], run["seed"])] = run["summary"]
    return methods, winners, runs


def main(with_dir, without_dir):
    on, on_win, on_runs = load(with_dir)
    off, off_win, off_runs = load(without_dir)
    scenes = sorted({s for s, _ in on}, key=natural)
    methods = sorted({m for _, m in on})
    print("| scene | " + " | ".join(
        f"{m} coverage off → on | {m} s < δ off (avoidable/unavoidable) → on" for m in methods)
        + " | winner off → on |")
    print("|---" * (1 + 2 * len(methods) + 1) + "|")
    for s in scenes:
        cells = []
        for m in methods:
            a, b = off[(s, m)], on[(s, m)]
            cells.append(f"{a['averageCoverage']['mean']:.3f} → {b['averageCoverage']['mean']:.3f}")
            cells.append(
                f"{a['meanAvoidableContactTime']:.2f}/{a['meanUnavoidableContactTime']:.2f} → "
                f"{b['meanAvoidableContactTime']:.2f}/{b['meanUnavoidableContactTime']:.2f}")
        print(f"| {s} | " + " | ".join(cells) + f" | {off_win[s]} → {on_win[s]} |")

    def avoidable_runs(runs):
        return sum(1 for r in runs.values() if r["avoidableContactTime"] > 0)

    def any_contact_runs(runs):
        return sum(1 for r in runs.values() if r["objectCollisionTime"] + r["cameraCollisionTime"] > 0)

    def unavoidable_without_event(runs):
        return sum(1 for r in runs.values()
                   if r["unavoidableContactTime"] > 0 and r["unavoidableContacts"] == 0)

    print()
    for name, runs in (("without the layer", off_runs), ("with the layer", on_runs)):
        print(f"- {name}: {len(runs)} runs, {any_contact_runs(runs)} with time below δ, "
              f"{avoidable_runs(runs)} with avoidable time below δ, "
              f"{unavoidable_without_event(runs)} unavoidable without an event")
    for m in methods:
        mean_on = sum(on[(s, m)]["averageCoverage"]["mean"] for s in scenes) / len(scenes)
        mean_off = sum(off[(s, m)]["averageCoverage"]["mean"] for s in scenes) / len(scenes)
        print(f"- {m}: mean average coverage over the {len(scenes)} scenes {mean_off:.4f} without, "
              f"{mean_on:.4f} with the layer ({mean_on - mean_off:+.4f})")
    lost = [s for s in scenes if off_win[s] in ("paper", "tie") and on_win[s] == "local"]
    print(f"- paper wins or ties the baseline without the layer on "
          f"{sum(off_win[s] in ('paper', 'tie') for s in scenes)} scenes, with it on "
          f"{sum(on_win[s] in ('paper', 'tie') for s in scenes)}; lost with the layer: "
          f"{', '.join(lost) if lost else 'none'}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
