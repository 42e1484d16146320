#!/usr/bin/python3
"""Histogram of the smallest angle per triangle from a `symmesh generate --report` file.
Usage: plot_quality.py REPORT.json OUT.png"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

report = json.load(open(sys.argv[1]))
q = report["quality"]
width = q["min_angle_histogram_bin_deg"]
counts = q["min_angle_histogram"]
edges = [width * i for i in range(len(counts))]
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.bar(edges, counts, width=width, align="edge", edgecolor="black")
ax.axvline(report["min_angle_requested_deg"], color="red", linestyle="--", label="requested bound")
ax.set_xlabel("smallest angle of a triangle (degrees)")
ax.set_ylabel("triangles")
ax.set_title(f"{q['triangles']} triangles, min {q['min_angle_deg']:.2f} deg, "
             f"{q['below_min_angle']} below the bound")
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120, metadata={"Software": None})
