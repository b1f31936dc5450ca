#!/usr/bin/env python3
"""Writes the two large adversarial scenes (64 cameras; a 1,000-edge target) next to itself.
Run it again after changing them; the JSON files are committed so tests need no Python."""
import json
import math
import pathlib

here = pathlib.Path(__file__).resolve().parent


def wkt_polygon(points):
    return "POLYGON((" + ",".join(f"{x:.9g} {y:.9g}" for x, y in points) + "))"


def camera(x, y, angle):
    return {"pos": f"POINT({x:.9g} {y:.9g})", "angle": round(angle, 6), "maxVelocity": 1,
            "maxAngularVelocity": 1}


def write(name, scene):
    (here / name).write_text(json.dumps(scene, indent=1) + "\n")


room = wkt_polygon([(-20, -20), (20, -20), (20, 20), (-20, 20)])
square = wkt_polygon([(-1, -1), (1, -1), (1, 1), (-1, 1)])

# The maximum number of cameras, on a circle, all looking at the middle.
write("cameras_64.json", {
    "description": "64 cameras on a circle around two targets.",
    "boundary": room,
    "targets": [{"shape": square, "path": "POLYGON((-3 0,3 0))"},
                {"shape": square, "path": "POLYGON((0 4))", "angularVelocity": 0.5}],
    "obstacles": [{"shape": square, "path": "POLYGON((0 -5))"}],
    "cameraFoV": 20,
    "cameras": [camera(15 * math.cos(2 * math.pi * k / 64), 15 * math.sin(2 * math.pi * k / 64),
                       360 * k / 64 + 180) for k in range(64)],
})

# A circle of 1,000 edges, moving and rotating, behind an obstacle.
circle = [(3 * math.cos(2 * math.pi * k / 1000), 3 * math.sin(2 * math.pi * k / 1000))
          for k in range(1000)]
write("target_1000_edges.json", {
    "description": "A moving, rotating target with 1,000 edges.",
    "boundary": room,
    "targets": [{"shape": wkt_polygon(circle), "path": "POLYGON((-5 0,5 0))",
                 "angularVelocity": 0.2}],
    "obstacles": [{"shape": square, "path": "POLYGON((0 -8))"}],
    "cameraFoV": 30,
    "cameras": [camera(0, -15, 90), camera(15, 15, -135), camera(-15, 10, -30)],
})
