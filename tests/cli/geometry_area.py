"""Area of a 2D templated geometry given by polygons: the sum over templates of the polygon's
area (shoelace, holes subtracted) times its number of instances (rigid maps keep areas).
Symbolic numbers (spec/input-format.md §2.1) are evaluated in floating point.
Usage: geometry_area.py GEOMETRY.json"""
import json
import math
import re
import sys


def value(text):
    expr = re.sub(r"(\d)pi", r"\1*math.pi", str(text))
    return float(eval(expr, {"__builtins__": {}}, {"cos": math.cos, "sin": math.sin, "math": math}))


def ring_area(ring):
    pts = [(value(x), value(y)) for x, y in ring]
    return abs(sum(pts[i][0] * pts[i - 1][1] - pts[i - 1][0] * pts[i][1] for i in range(len(pts)))) / 2


doc = json.load(open(sys.argv[1]))
total = 0.0
for t in doc["templates"]:
    area = ring_area(t["polygon"]) - sum(ring_area(h) for h in t.get("holes", []))
    total += area * len(t["instances"])
print(repr(total))
