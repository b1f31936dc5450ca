#!/usr/bin/env python3
"""Before and after, side by side: two batches of the same scenes, methods and seeds, e.g. the
published protocol before and after a change that moves results on purpose. Per scene and
method: mean ± sd of the average coverage in each, how many runs are byte-identical in what
they describe (series, events, summary), and each method's verdict against the reference as
each batch's summary gives it; then the mean over the scenes and the wins/ties/losses.

    camcov bench --scenes DIR --seeds 20 --videos none --explorer none --out before
    ... (the change) ...
    camcov bench --scenes DIR --seeds 20 --videos none --explorer none --out after
    scripts/compare_batches.py before after
"""
import json
import re
import sys
from pathlib import Path


def natural(name):
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


def load(folder):
    summary = json.loads((Path(folder) / "summary.json").read_text())
    cells = {(m["scene"], m["method"]): m["averageCoverage"] for m in summary["methods"]}
    verdicts = {(c["scene"], c["method"]): c["winner"] for c in summary["comparisons"]}
    runs = {}
    for f in (Path(folder) / "runs").glob("*.json"):
        run = json.loads(f.read_text())
        runs[(run["scene"]["name"], run["method"], run["seed"])] = {
            k: run[k] for k in ("series", "events", "summary")}
    return summary["reference"], cells, verdicts, runs


def verdict(winner, method, reference):
    if winner is None:
        return "—"
    return "tie" if winner == "tie" else ("win" if winner == method else "loss")


def main(before_dir, after_dir):
    reference, before, before_verdicts, before_runs = load(before_dir)
    _, after, after_verdicts, after_runs = load(after_dir)
    scenes = sorted({s for s, _ in before}, key=natural)
    methods = sorted({m for _, m in before}, key=lambda m: (m != reference, m))
    print("| scene | " + " | ".join(
        f"{m} before → after | {m} runs unchanged" +
        ("" if m == reference else f" | {m} vs {reference} before → after") for m in methods) +
        " |")
    print("|---" * (1 + sum(2 if m == reference else 3 for m in methods)) + "|")
    totals = {}
    for scene in scenes:
        row = [scene]
        for m in methods:
            b, a = before[(scene, m)], after[(scene, m)]
            seeds = [k for k in before_runs if k[0] == scene and k[1] == m]
            same = sum(1 for k in seeds if before_runs[k] == after_runs.get(k))
            row.append(f"{b['mean']:.3f} ± {b['sd']:.3f} → {a['mean']:.3f} ± {a['sd']:.3f}")
            row.append(f"{same}/{len(seeds)}")
            if m != reference:
                vb = verdict(before_verdicts.get((scene, m)), m, reference)
                va = verdict(after_verdicts.get((scene, m)), m, reference)
                row.append(f"{vb} → {va}")
                for label, v in (("before", vb), ("after", va)):
                    counts = totals.setdefault((m, label), {"win": 0, "tie": 0, "loss": 0})
                    if v in counts:
                        counts[v] += 1
        print("| " + " | ".join(row) + " |")
    print()
    for m in methods:
        b = sum(before[(s, m)]["mean"] for s in scenes) / len(scenes)
        a = sum(after[(s, m)]["mean"] for s in scenes) / len(scenes)
        line = f"- {m}: mean average coverage over the {len(scenes)} scenes {b:.4f} → {a:.4f}"
        if m != reference:
            cb, ca = totals[(m, "before")], totals[(m, "after")]
            line += (f"; against {reference} {cb['win']} wins, {cb['tie']} ties, {cb['loss']} "
                     f"losses → {ca['win']}, {ca['tie']}, {ca['loss']}")
        print(line)
    same = sum(1 for k in before_runs if before_runs[k] == after_runs.get(k))
    print(f"- runs byte-identical in series, events and summary: {same} of {len(before_runs)}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
