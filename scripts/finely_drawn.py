#!/usr/bin/env python3
"""Writes finely drawn copies of scenes: every target and obstacle outline (and each of its
deformation keyframes) smoothed by ROUNDS rounds of Chaikin's corner cutting, so a ring of n
vertices becomes one of n * 2^ROUNDS on a smooth curve through the midpoints of its sides. How
our method's camcov.detail is judged (docs/method.md, "Finely drawn objects"): the same scenes,
drawn as a survey or a segmentation would draw them.

    scripts/finely_drawn.py IN_DIR OUT_DIR [--rounds 5]
    scripts/family_scenes.sh tune 4 tune && scripts/finely_drawn.py tune tune_fine
"""
import argparse
import json
import pathlib
import re
import sys

NUMBER = r"[-+0-9.eE]+"


def parse_ring(wkt):
    match = re.fullmatch(r"\s*POLYGON\s*\(\((.*)\)\)\s*", wkt)
    if not match:
        raise ValueError(f"not a polygon: {wkt[:60]}")
    points = []
    for pair in match.group(1).split(","):
        x, y = pair.split()
        points.append((float(x), float(y)))
    if len(points) > 1 and points[0] == points[-1]:
        points.pop()  # a closed ring's repeated first vertex
    return points


def format_ring(points):
    return "POLYGON((" + ",".join(f"{x!r} {y!r}" for x, y in points) + "))"


def chaikin(points, rounds):
    """Each side a-b gives its points at 1/4 and 3/4: the corners are cut, the ring closed."""
    for _ in range(rounds):
        cut = []
        for i, a in enumerate(points):
            b = points[(i + 1) % len(points)]
            cut.append((0.75 * a[0] + 0.25 * b[0], 0.75 * a[1] + 0.25 * b[1]))
            cut.append((0.25 * a[0] + 0.75 * b[0], 0.25 * a[1] + 0.75 * b[1]))
        points = cut
    return points


def finely_drawn(scene, rounds):
    for kind in ("targets", "obstacles"):
        for thing in scene.get(kind) or []:
            if not isinstance(thing, dict) or "shape" not in thing:
                continue
            thing["shape"] = format_ring(chaikin(parse_ring(thing["shape"]), rounds))
            for keyframe in (thing.get("deformation") or {}).get("keyframes", []):
                keyframe["shape"] = format_ring(chaikin(parse_ring(keyframe["shape"]), rounds))
    note = f"finely drawn ({rounds} rounds of corner cutting)"
    scene["description"] = f"{note}: {scene['description']}" if scene.get("description") else note
    return scene


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("inputs", type=pathlib.Path)
    parser.add_argument("outputs", type=pathlib.Path)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    if not args.inputs.is_dir() or not 0 <= args.rounds <= 12:
        print("finely_drawn.py: IN_DIR must be a folder of scenes, ROUNDS 0 to 12", file=sys.stderr)
        return 2
    args.outputs.mkdir(parents=True, exist_ok=True)
    count = 0
    for path in sorted(args.inputs.glob("*.json")):
        try:
            scene = finely_drawn(json.loads(path.read_text()), args.rounds)
        except (ValueError, KeyError, TypeError, AttributeError) as error:
            print(f"finely_drawn.py: {path}: {error}", file=sys.stderr)
            return 2
        (args.outputs / path.name).write_text(json.dumps(scene, indent=1) + "\n")
        count += 1
    print(f"wrote {count} finely drawn scenes to {args.outputs}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
