#!/usr/bin/python3
"""Independent surface meshing + interface merging (--method merge in 3D, Section 5.1.1 with
Algorithm 5.4, spec/generation.md#merge-3d) against the boundary-patch pipeline (Algorithm 5.7 by
--method auto: rotational for the TSV slices, reflective for the FinFET, bpp otherwise), issue 18,
docs/benchmarks/merge_3d.md.

For built-in 3D objects at two sizes, `symmesh generate` runs with both methods, the same mesher
(TetGen -pq, same --size), side by side, repeats interleaved. Per run: tetrahedra of AT, the
generation span of the report, the certificate, the whole command's wall time and peak RSS (GNU
time), the smallest dihedral angle, and for merge the close pairs Algorithm 5.2 merged and the
overlay points (Algorithms 5.3/5.4). Writes merge_3d.csv (every run), merge_3d.png and
merge_3d.md (medians, ratios merge / reference) from the same run.

Usage: merge_3d.py SYMMESH OUTDIR [--repeats R]
"""
import argparse
import csv
import json
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generate_2d import commit, cpu_model  # noqa: E402

OBJECTS = [("cube-halves", (0.3, 0.15)), ("finfet", (0.3, 0.15)), ("tsv-8", (0.3, 0.15)),
           ("tsv-32", (0.3, 0.15)), ("multi-tsv", (0.3,))]
LOAD = os.getloadavg()[0]
FIELDS = ["object", "size", "method", "method_run", "repeat", "cells", "seconds_generation",
          "seconds_certificate", "seconds_process", "rss_process_bytes", "min_dihedral_deg",
          "pairs_merged", "points_moved", "points_inserted", "rounds"]


def run(symmesh, geometry, size, method, tmp):
    report = os.path.join(tmp, "report.json")
    out = os.path.join(tmp, "out.vtu")
    rss = os.path.join(tmp, "rss.txt")
    cmd = [symmesh, "generate", geometry, "--size", str(size), "--method", method, "-o", out,
           "--report", report, "--quiet"]
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
            "min_dihedral_deg": r["quality"]["min_dihedral_deg"],
            "pairs_merged": merging.get("pairs_merged", ""),
            "points_moved": merging.get("points_moved", ""),
            "points_inserted": merging.get("points_inserted", ""),
            "rounds": merging.get("rounds", "")}


def median(rows, key):
    return statistics.median(float(r[key]) for r in rows)


def summarise(rows, outdir, wall, argv, repeats):
    groups = {}
    for r in rows:
        groups.setdefault((r["object"], float(r["size"])), {}).setdefault(r["method"], []).append(r)
    table = []
    for (name, size), by in groups.items():
        a, m = by["auto"], by["merge"]
        table.append({
            "object": name, "size": size, "reference": a[0]["method_run"],
            "cells_a": int(median(a, "cells")), "cells_m": int(median(m, "cells")),
            "gen_a": median(a, "seconds_generation"), "gen_m": median(m, "seconds_generation"),
            "cert_a": median(a, "seconds_certificate"), "cert_m": median(m, "seconds_certificate"),
            "wall_a": median(a, "seconds_process"), "wall_m": median(m, "seconds_process"),
            "rss_a": median(a, "rss_process_bytes"), "rss_m": median(m, "rss_process_bytes"),
            "dih_a": median(a, "min_dihedral_deg"), "dih_m": median(m, "min_dihedral_deg"),
            "merged": int(median(m, "pairs_merged")), "inserted": int(median(m, "points_inserted"))})
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.5))
    names = [f"{t['object']}\nh={t['size']:g}" for t in table]
    xs = range(len(table))
    ax[0].bar([x - 0.2 for x in xs], [t["wall_a"] for t in table], 0.4, label="Alg. 5.7 (auto)")
    ax[0].bar([x + 0.2 for x in xs], [t["wall_m"] for t in table], 0.4, label="merge")
    ax[0].set_yscale("log")
    ax[0].set_ylabel("whole command, s (median)")
    ax[1].bar([x - 0.2 for x in xs], [t["dih_a"] for t in table], 0.4, label="Alg. 5.7 (auto)")
    ax[1].bar([x + 0.2 for x in xs], [t["dih_m"] for t in table], 0.4, label="merge")
    ax[1].set_ylabel("smallest dihedral angle of AT, degrees")
    for a in ax:
        a.set_xticks(list(xs))
        a.set_xticklabels(names, rotation=90, fontsize=7)
        a.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "merge_3d.png"), dpi=110)
    lines = [
        "# Independent surface meshing + interface merging vs the boundary patch partition (3D)",
        "",
        f"Written by `bench/merge_3d.py` ({' '.join(argv)}) at commit {commit()}, "
        f"{time.strftime('%Y-%m-%d', time.gmtime())}; {wall:.0f} s of wall time.",
        f"- machine: {platform.machine()}, {os.cpu_count()} cores, {cpu_model()}, "
        f"{platform.platform()}; load average at the start {LOAD:.2f} (other processes: the "
        "ratios are side by side, the absolute times shift with the load)",
        "- every run: `symmesh generate OBJ --size H --method auto|merge -o out.vtu --report "
        "r.json`, the two side by side, repeats interleaved; medians of "
        f"{repeats} repeats. `merge` surface-meshes every face of every template on its own and "
        "merges the interfaces by Algorithms 5.1–5.4 (spec/generation.md#merge-3d); the reference "
        "is Algorithm 5.7 with the symmetric method `auto` picks (column 'reference'): one "
        "surface mesh per face class. Same mesher (TetGen), same size; both use the rotation "
        "shortcut (copies 0 and 1) on the TSV slices.",
        "- generation: the report's span before the certificate (merge: surface meshes, merging "
        "+ SVB, TetGen); wall and RSS: the whole command (read, generate, certify, write the "
        "binary .vtu) under GNU time.",
        "",
        "| object | size | reference | tetrahedra ref / merge | merged / overlay points | "
        "generation s ref / merge | certificate s ref / merge | wall s ref / merge (ratio) | "
        "peak RSS MiB ref / merge | smallest dihedral ° ref / merge |",
        "|---|---|---|---|---|---|---|---|---|---|"]
    for t in table:
        lines.append(
            f"| {t['object']} | {t['size']:g} | {t['reference']} | {t['cells_a']} / "
            f"{t['cells_m']} | {t['merged']} / {t['inserted']} | {t['gen_a']:.3f} / "
            f"{t['gen_m']:.3f} | {t['cert_a']:.3f} / {t['cert_m']:.3f} | {t['wall_a']:.3f} / "
            f"{t['wall_m']:.3f} ({t['wall_m'] / t['wall_a']:.2f}) | {t['rss_a'] / 2**20:.0f} / "
            f"{t['rss_m'] / 2**20:.0f} | {t['dih_a']:.1f} / {t['dih_m']:.1f} |")
    ratios = [t["wall_m"] / t["wall_a"] for t in table]
    changed = [t for t in table if t["merged"] > 0 or t["inserted"] > 0]
    lines += [
        "",
        "![whole-command time and smallest dihedral angle](merge_3d.png)",
        "",
        "## Reading",
        f"- Whole command, merge / reference: {min(ratios):.2f}–{max(ratios):.2f} (median "
        f"{statistics.median(ratios):.2f}).",
        f"- The merge changed the surfaces in {len(changed)} of {len(table)} cases: "
        + (", ".join(f"{t['object']} at {t['size']:g} ({t['merged']} merges, {t['inserted']} "
                     f"overlay points; smallest dihedral {t['dih_a']:.1f}° → {t['dih_m']:.1f}°)"
                     for t in changed) if changed else "none") + ".",
        "- Where the faces that meet see the same 2D input in their own frames (the TSV slices' "
        "interfaces, the cube halves' mirror face), independent meshing gives the same "
        "triangulation and the merge has nothing to do; its cost is then meshing every face "
        "instead of one per class.",
        ""]
    open(os.path.join(outdir, "merge_3d.md"), "w").write("\n".join(lines))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("symmesh")
    ap.add_argument("outdir")
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    rows = []
    start = time.time()
    with tempfile.TemporaryDirectory() as tmp:
        for name, sizes in OBJECTS:
            geometry = os.path.join(tmp, name + ".json")
            subprocess.run([a.symmesh, "example", name, "-o", geometry], check=True)
            for size in sizes:
                for rep in range(1, a.repeats + 1):
                    for method in ("auto", "merge"):
                        r = run(a.symmesh, geometry, size, method, tmp)
                        r.update({"object": name, "size": size, "method": method, "repeat": rep})
                        rows.append(r)
                        print(f"[{time.time() - start:7.1f} s] {name} h={size} {method} rep {rep}: "
                              f"{r['cells']} cells, {r['seconds_process']:.3f} s", file=sys.stderr,
                              flush=True)
    with open(os.path.join(a.outdir, "merge_3d.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)
    summarise(rows, a.outdir, time.time() - start, ["bench/merge_3d.py"] + sys.argv[1:], a.repeats)


if __name__ == "__main__":
    main()
