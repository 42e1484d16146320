#!/usr/bin/env python3
"""Draws the point data `u` of a 2D structure instance written by `symmesh solve` (.vtu) as a
filled contour picture with the mesh edges (SVG or PNG by the extension).

Usage: plot_solution.py SOLUTION.vtu -o PICTURE.svg [--title TEXT]

Deterministic: the same input gives the same bytes (no date in the metadata, fixed SVG ids).
Exits 2 with one line on a missing file, a 3D mesh or a file without `u`.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.hashsalt"] = "symmesh"
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import meshio  # noqa: E402


def fail(message):
    sys.stderr.write("plot_solution: error: %s\n" % message)
    sys.exit(2)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("solution")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--title", default="u")
    a = ap.parse_args()
    if not os.path.isfile(a.solution):
        fail("%s: cannot open file" % a.solution)
    ext = os.path.splitext(a.output)[1].lower()
    if ext not in (".svg", ".png"):
        fail("-o: the picture must end in .svg or .png")
    m = meshio.read(a.solution)
    if "u" not in m.point_data:
        fail("%s: no point data 'u' (write it with symmesh solve)" % a.solution)
    triangles = [c.data for c in m.cells if c.type == "triangle"]
    if not triangles or m.points.shape[1] > 2 and abs(m.points[:, 2]).max() > 0:
        fail("%s: not a 2D triangle mesh" % a.solution)
    tri = mtri.Triangulation(m.points[:, 0], m.points[:, 1], triangles[0])
    fig, ax = plt.subplots(figsize=(6, 5.2))
    filled = ax.tricontourf(tri, m.point_data["u"], levels=20, cmap="viridis")
    ax.triplot(tri, color="black", linewidth=0.15, alpha=0.35)
    ax.set_aspect("equal")
    ax.set_title(a.title)
    fig.colorbar(filled, ax=ax, label="u")
    tmp = a.output + ".part" + ext
    fig.savefig(tmp, metadata={"Date": None} if ext == ".svg" else {"Software": None}, dpi=120)
    os.replace(tmp, a.output)


if __name__ == "__main__":
    main()
