#!/usr/bin/env python3
"""Writes examples/you2004-fig8c.json: seed 000 Fig. 8c, a model of three-, four- and
five-sided patches. Three polygonal holes in one curved sheet z = a x^2 + b y^2 + c x y, each
ringed by strips of the sheet (a strip's border t0 is one side of its hole) and closed by a fill
(scene kind "fill") that meets every side G1. Run from the repository root."""
import json
import math


def num(x):
    return "(%.17g)" % x


def polygon(n, cx, cy, radius, turn, prefix):
    patches, borders = [], []
    for k in range(n):
        t0, t1 = turn + 2 * math.pi * k / n, turn + 2 * math.pi * (k + 1) / n
        x0, y0 = cx + radius * math.cos(t0), cy + radius * math.sin(t0)
        x1, y1 = cx + radius * math.cos(t1), cy + radius * math.sin(t1)
        mx, my = (x0 + x1) / 2 - cx, (y0 + y1) / 2 - cy
        ml = math.hypot(mx, my)
        X = "%s + %s*v + %s*t" % (num(x0), num(x1 - x0), num(0.6 * mx / ml))
        Y = "%s + %s*v + %s*t" % (num(y0), num(y1 - y0), num(0.6 * my / ml))
        Z = "a*(%s)^2 + b*(%s)^2 + c*(%s)*(%s)" % (X, Y, X, Y)
        name = "%s_strip%d" % (prefix, k)
        patches.append({"name": name, "kind": "surface", "t_range": [0, 1], "v_range": [0, 1], "x": X, "y": Y, "z": Z})
        borders.append({"patch": name, "at": "t0"})
    patches.append({"name": prefix, "kind": "fill", "borders": borders, "height": "lift"})
    return patches


scene = {
    "format": "pdesurf-scene",
    "version": 4,
    "id": "you2004-fig8c",
    "title": "A model of three-, four- and five-sided patches",
    "description": "Three holes in one curved sheet z = a x^2 + b y^2 + c x y (a triangle, a square and a pentagon), "
    "each ringed by strips of the sheet and closed by a fill: a 4th-order PDE patch whose border u = 0 runs once around "
    "the hole (piecewise, one side per strip) and whose u = 1 is a regular centre. Every fill meets every strip G1 "
    "(the certificate checks each side on its open interval); the centres' normals converge and nothing folds. "
    "lift raises each centre along the hole's normal (1: by the strips' own rise).",
    "source": {"paper": "seed 000, Fig. 8: models of many patches", "figure": "Fig. 8c"},
    "parameters": {
        "a": {"value": 0.12, "min": -0.3, "max": 0.3, "label": "curvature along x (a x²)"},
        "b": {"value": -0.08, "min": -0.3, "max": 0.3, "label": "curvature along y (b y²)"},
        "c": {"value": 0.05, "min": -0.3, "max": 0.3, "label": "twist (c xy)"},
        "lift": {"value": 1, "min": 0, "max": 2, "label": "the fills' centre lift"},
    },
    "patches": polygon(3, -3.2, 0, 1.0, 0.0, "triangle") + polygon(4, 0, 0, 1.1, 0.785398, "square") + polygon(5, 3.3, 0, 1.1, 0.2, "pentagon"),
}
with open("examples/you2004-fig8c.json", "w") as f:
    json.dump(scene, f, indent=2)
    f.write("\n")
