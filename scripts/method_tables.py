#!/usr/bin/env python3
"""The tables of docs/method.md ("Our method") from a results folder: per scene, every
method's mean ± sd of average coverage and our method's verdicts against the reference and
the paper's (as the batch's summary.json gives them); then, for the scenes the bench searched
an offline optimum for, each method's median final coverage as a fraction of it.

    camcov bench --scenes ../shared/coverage_scenes --seeds 20 --videos none --explorer none \
        --out published
    scripts/method_tables.py published
"""
import json
import sys
from pathlib import Path

OURS, PAPER = "camcov", "paper"


def verdict(comparison, method):
    if comparison is None or not comparison["winner"]:
        return "—"
    w = comparison["winner"]
    return "tie" if w == "tie" else ("win" if w == method else "loss")


def main(folder):
    folder = Path(folder)
    s = json.loads((folder / "summary.json").read_text())
    methods = json.loads((folder / "batch.json").read_text())["methods"]
    rows = {(m["scene"], m["method"]): m for m in s["methods"]}
    against_reference = {(c["scene"], c["method"]): c for c in s["comparisons"]}
    pairs = {(c["scene"], c["method"], c["against"]): c for c in s.get("pairs", [])}
    reference = s["reference"]

    print("| scene | " + " | ".join(methods) +
          f" | {OURS} vs {reference} | {OURS} vs {PAPER} (Δ) |")
    print("|---" * (len(methods) + 3) + "|")
    for scene in s["scenes"]:
        cells = []
        for m in methods:
            c = rows.get((scene, m))
            cells.append("—" if c is None or c["runs"] == 0 else
                         f"{c['averageCoverage']['mean']:.3f} ± {c['averageCoverage']['sd']:.3f}")
        pair = pairs.get((scene, OURS, PAPER))
        delta = f" ({pair['meanCoverageDifference']:+.3f})" if pair else ""
        print(f"| {scene} | " + " | ".join(cells) +
              f" | {verdict(against_reference.get((scene, OURS)), OURS)}"
              f" | {verdict(pair, OURS)}{delta} |")
    means = []
    for m in methods:
        values = [rows[(sc, m)]["averageCoverage"]["mean"] for sc in s["scenes"] if (sc, m) in rows]
        means.append(f"**{sum(values) / len(values):.4f}**" if values else "—")
    print(f"| **mean over {len(s['scenes'])}** | " + " | ".join(means) + " | | |")
    print()
    for t in s["totals"] + s.get("pairTotals", []):
        print(f"- {t['method']} against {t.get('against', reference)}: wins {t['wins']}, "
              f"ties {t['ties']}, losses {t['losses']}")

    optima = sorted((folder / "optimum").glob("*.json")) if (folder / "optimum").is_dir() else []
    if not optima:
        return
    print()
    print("| scene | optimum: coverage (reward) | " +
          " | ".join(f"{m}: final, median" for m in methods) + " |")
    print("|---" * (len(methods) + 2) + "|")
    near = {m: 0 for m in methods}
    order = {name: i for i, name in enumerate(s["scenes"])}
    for f in sorted(optima, key=lambda p: order.get(p.stem, len(order))):
        o = json.loads(f.read_text())
        best = o["best"]["coverage"]
        cells = []
        for m in methods:
            c = rows.get((f.stem, m))
            if c is None or "finalCoverage" not in c or c["finalCoverage"]["count"] == 0:
                cells.append("—")
                continue
            final = c["finalCoverage"]["median"]
            reached = best > 0 and final >= 0.98 * best
            near[m] += reached
            share = f" ({100 * final / best:.1f} %)" if best > 0 else ""
            cells.append(f"{final:.3f}{share}{' ✓' if reached else ''}")
        print(f"| {f.stem} | {best:.4f} ({o['best']['reward']:.4f}) | " + " | ".join(cells) + " |")
    print("| within 2 % | | " + " | ".join(f"{near[m]} of {len(optima)}" for m in methods) + " |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
