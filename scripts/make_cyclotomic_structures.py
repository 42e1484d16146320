#!/usr/bin/env python3
"""Writes the built-in exact templated geometries of issue 4 to data/ (spec/number-type.md).

Every coordinate is exact: rationals and the symbolic numbers cos(2pi*k/n), sin(2pi*k/n) of the
input format, so `symmesh check` reads them in the real cyclotomic field K_m it needs.

  ngon_slice_<n>.json  regular n-gon (circumradius 1): one slice template, n rotations
  ngon_sao_<n>.json    the same with the small-angle optimisation of Section 6.3.2: a centre
                       n-gon of radius 1/2 (instanced once) and a ring slice (n rotations)
  star_5_half_slices.json  regular five-pointed star {5/2}: one reflective-rotational
                       half-slice (Algorithm 6.5 form), 5 rotations and 5 rotated reflections

Usage: scripts/make_cyclotomic_structures.py [DATA_DIR]   (default: data/ next to scripts/)
"""
import json
import os
import sys

ORDERS = [5, 8, 16, 32, 64, 128]


def cos(k, n, factor=None):
    return (factor + "*" if factor else "") + f"cos(2pi*{k}/{n})"


def sin(k, n, factor=None):
    return (factor + "*" if factor else "") + f"sin(2pi*{k}/{n})"


def rotation(k, n):
    return {"rotation": {"order": n, "k": k}}


def document(description, templates):
    return {"symmesh": "templated-structure/1", "dimension": 2, "description": description,
            "templates": templates}


def ngon_slice(n):
    return document(
        f"Regular {n}-gon with circumradius 1 as a templated geometry (Section 6.3): one slice "
        f"template, the triangle (0,0), (1,0), (cos 2pi/{n}, sin 2pi/{n}), instanced by the {n} "
        f"rotations by 2pi*k/{n} about the origin. Exact in K_m for m = lcm(4, {n}). Expected: "
        f"a valid templated geometry; consecutive slices meet along a ray, the others only at "
        f"the centre.",
        [{"name": "slice", "kind": "geometry",
          "polygon": [["0", "0"], ["1", "0"], [cos(1, n), sin(1, n)]],
          "instances": [{"transformation": rotation(k, n)} for k in range(n)]}])


def ngon_sao(n):
    return document(
        f"Regular {n}-gon with circumradius 1 split by the small-angle optimisation of Section "
        f"6.3.2: a centre template P, the regular {n}-gon of circumradius 1/2 aligned with the "
        f"slice start (a vertex at angle 0), instanced once, and a ring slice template, the "
        f"quadrilateral (1/2,0), (1,0), (cos 2pi/{n}, sin 2pi/{n}), (1/2)(cos 2pi/{n}, "
        f"sin 2pi/{n}), instanced by the {n} rotations by 2pi*k/{n}. No template has the small "
        f"angle 2pi/{n} at the centre. Expected: a valid templated geometry.",
        [{"name": "centre", "kind": "geometry",
          "polygon": [[cos(k, n, "1/2"), sin(k, n, "1/2")] for k in range(n)],
          "instances": [{"transformation": {"identity": {}}}]},
         {"name": "ring_slice", "kind": "geometry",
          "polygon": [["1/2", "0"], ["1", "0"], [cos(1, n), sin(1, n)],
                      [cos(1, n, "1/2"), sin(1, n, "1/2")]],
          "instances": [{"transformation": rotation(k, n)} for k in range(n)]}])


def star():
    # Inner vertex of the regular star {5/2} with tips on the unit circle: radius
    # r = cos(2pi/5)/cos(2pi/10) at angle 2pi/10, so r*cos(2pi/10) = cos(2pi/5).
    inner = ["cos(2pi*1/5)", "cos(2pi*1/5)/cos(2pi*1/10)*sin(2pi*1/10)"]
    reflect_x = {"reflection": {"angle": {"order": 2, "k": 0}}}  # the line at angle 0
    instances = [{"transformation": rotation(k, 5)} for k in range(5)]
    instances += [{"transformation": {"compose": [rotation(k, 5), reflect_x]}} for k in range(5)]
    return document(
        "Regular five-pointed star {5/2} (tips on the unit circle at angles 2pi*k/5, inner "
        "vertices at radius cos(2pi/5)/cos(2pi/10) at angles 2pi*(2k+1)/10) as a templated "
        "geometry in the form of Algorithm 6.5: one half-slice template, the triangle between the "
        "reflecting line at angle 0 and the line at angle pi/5, (0,0), (1,0), inner vertex; "
        "instances rot(2pi*k/5) and rot(2pi*k/5) o refl(x-axis), k = 0..4 (10 half-slices). "
        "Exact in K_20. Expected: a valid templated geometry.",
        [{"name": "half_slice", "kind": "geometry",
          "polygon": [["0", "0"], ["1", "0"], inner],
          "instances": instances}])


def write(directory, name, doc):
    path = os.path.join(directory, name)
    with open(path, "w", encoding="utf-8") as f:
        json.dump(doc, f, indent=2)
        f.write("\n")
    print(path)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    directory = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "data")
    for n in ORDERS:
        write(directory, f"ngon_slice_{n}.json", ngon_slice(n))
        write(directory, f"ngon_sao_{n}.json", ngon_sao(n))
    write(directory, "star_5_half_slices.json", star())


if __name__ == "__main__":
    main()
