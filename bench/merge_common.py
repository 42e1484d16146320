"""What bench/merge_2d.py and bench/merge_3d.py share: one `symmesh generate` run measured as the
whole command (GNU time: wall time and the command's own peak RSS), the methods side by side with
the repeats interleaved, the CSV of every run, the medians per object and size, and the plot of
whole-command time and smallest angle. Each script keeps its objects and its report's text.
"""
import csv
import json
import os
import statistics
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

FIELDS = ["object", "size", "method", "method_run", "repeat", "cells", "seconds_generation",
          "seconds_certificate", "seconds_process", "rss_process_bytes", "QUALITY",
          "pairs_merged", "points_moved", "points_inserted", "rounds"]


def fields(quality_key):
    return [quality_key if f == "QUALITY" else f for f in FIELDS]


def run(symmesh, geometry, size, method, tmp, extra, quality_key):
    """One `symmesh generate` with `extra` options; the report's numbers and the whole command's."""
    report = os.path.join(tmp, "report.json")
    out = os.path.join(tmp, "out.vtu")
    rss = os.path.join(tmp, "rss.txt")
    cmd = ([symmesh, "generate", geometry, "--size", str(size)] + list(extra) +
           ["--method", method, "-o", out, "--report", report, "--quiet"])
    # GNU time reports the command's own peak RSS: wait4 on a child Python forked would count the
    # interpreter's pages the child had before exec.
    start = time.perf_counter()
    subprocess.run(["/usr/bin/time", "-f", "%M", "-o", rss] + cmd, check=True)
    seconds = time.perf_counter() - start
    r = json.load(open(report))
    b = r["seconds_breakdown"]
    merging = r.get("interface_merging", {})
    return {"cells": r["cells_structure_instance"], "method_run": r["method"],
            "seconds_generation": b["boundary_patch_partition"] + b["line_meshes"] +
            b["template_meshing"] + b["svb"],
            "seconds_certificate": b["lemma_4_2_certificate"], "seconds_process": seconds,
            "rss_process_bytes": int(open(rss).read().split()[-1]) * 1024,
            quality_key: r["quality"][quality_key],
            "pairs_merged": merging.get("pairs_merged", ""),
            "points_moved": merging.get("points_moved", ""),
            "points_inserted": merging.get("points_inserted", ""),
            "rounds": merging.get("rounds", "")}


def measure(symmesh, cases, methods, repeats, tmp, extra, quality_key):
    """Every (object, geometry file, sizes) of `cases` with every method, repeats interleaved."""
    rows = []
    start = time.time()
    for name, geometry, sizes in cases:
        for size in sizes:
            for rep in range(1, repeats + 1):
                for method in methods:
                    r = run(symmesh, geometry, size, method, tmp, extra, quality_key)
                    r.update({"object": name, "size": size, "method": method, "repeat": rep})
                    rows.append(r)
                    print(f"[{time.time() - start:7.1f} s] {name} h={size} {method} rep {rep}: "
                          f"{r['cells']} cells, {r['seconds_process']:.3f} s", file=sys.stderr,
                          flush=True)
    return rows


def write_csv(path, quality_key, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields(quality_key))
        w.writeheader()
        w.writerows(rows)


def median(rows, key):
    return statistics.median(float(r[key]) for r in rows)


def medians(rows, reference, quality_key):
    """Per (object, size): medians of the reference method's runs and of merge's."""
    groups = {}
    for r in rows:
        groups.setdefault((r["object"], float(r["size"])), {}).setdefault(r["method"], []).append(r)
    table = []
    for (name, size), by in groups.items():
        a, m = by[reference], by["merge"]
        table.append({
            "object": name, "size": size, "reference": a[0]["method_run"],
            "cells_ref": int(median(a, "cells")), "cells_merge": int(median(m, "cells")),
            "gen_ref": median(a, "seconds_generation"), "gen_merge": median(m, "seconds_generation"),
            "cert_ref": median(a, "seconds_certificate"),
            "cert_merge": median(m, "seconds_certificate"),
            "wall_ref": median(a, "seconds_process"), "wall_merge": median(m, "seconds_process"),
            "rss_ref": median(a, "rss_process_bytes"), "rss_merge": median(m, "rss_process_bytes"),
            "quality_ref": median(a, quality_key), "quality_merge": median(m, quality_key),
            "merged": int(median(m, "pairs_merged")),
            "inserted": int(median(m, "points_inserted"))})
    return table


def plot(table, path, names, reference_label, quality_label, figsize, fontsize):
    """Whole-command time (log) and smallest angle, reference beside merge, per table row."""
    fig, ax = plt.subplots(1, 2, figsize=figsize)
    xs = range(len(table))
    for k, (key, label) in enumerate((("wall", "whole command, s (median)"),
                                      ("quality", quality_label))):
        ax[k].bar([x - 0.2 for x in xs], [t[key + "_ref"] for t in table], 0.4,
                  label=reference_label)
        ax[k].bar([x + 0.2 for x in xs], [t[key + "_merge"] for t in table], 0.4, label="merge")
        ax[k].set_ylabel(label)
    ax[0].set_yscale("log")
    for a in ax:
        a.set_xticks(list(xs))
        a.set_xticklabels(names, rotation=90, fontsize=fontsize)
        a.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
