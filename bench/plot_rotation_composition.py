#!/usr/bin/python3
"""Plot docs/benchmarks/cyclotomic_vs_core.csv: median time vs n (log-log), both types.

Usage: plot_rotation_composition.py CSV PNG
Timeouts are drawn at the limit with an upward triangle and a "> limit" label; each repeat is
a small dot behind the median line; (type, n) not run (a smaller n was already over the limit)
are listed below the plot.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    limit = max(float(r["limit_seconds"]) for r in rows)
    style = {"cyclotomic": ("tab:blue", "o", "Cyclotomic K_lcm(4,n) (symmesh)"),
             "core": ("tab:red", "s", "CORE::Expr (Epeck_with_sqrt)")}
    fig, ax = plt.subplots(figsize=(7, 4.5))
    notes = []
    for t, (color, marker, label) in style.items():
        med = sorted((r for r in rows if r["type"] == t and r["repeat"] == "median"
                      and r["status"] in ("ok", "timeout")), key=lambda r: int(r["n"]))
        reps = [r for r in rows if r["type"] == t and r["repeat"] != "median"
                and r["status"] == "ok"]
        ax.scatter([int(r["n"]) for r in reps], [max(float(r["seconds"]), 1e-6) for r in reps],
                   color=color, s=8, alpha=0.4)
        ok = [r for r in med if r["status"] == "ok"]
        to = [r for r in med if r["status"] == "timeout"]
        xs = [int(r["n"]) for r in med]
        ys = [max(float(r["seconds"]), 1e-6) for r in med]
        # Solid between finished medians, dotted into a timeout (a lower bound only).
        for (x0, y0, r0), (x1, y1, r1) in zip(zip(xs, ys, med), list(zip(xs, ys, med))[1:]):
            dotted = "timeout" in (r0["status"], r1["status"])
            ax.plot([x0, x1], [y0, y1], color=color, linestyle=":" if dotted else "-", alpha=0.7)
        ax.plot([int(r["n"]) for r in ok], [max(float(r["seconds"]), 1e-6) for r in ok],
                linestyle="none", marker=marker, color=color, label=label + " (median)")
        if to:
            ax.plot([int(r["n"]) for r in to], [float(r["seconds"]) for r in to],
                    linestyle="none", marker="^", markersize=10, color=color,
                    label=f"{t}: > {limit:g} s limit (killed)")
            for r in to:
                ax.annotate(f"> {float(r['seconds']):g} s", (int(r["n"]), float(r["seconds"])),
                            textcoords="offset points", xytext=(0, 8), ha="center",
                            fontsize=8, color=color)
        skipped = [r["n"] for r in rows if r["type"] == t and r["repeat"] == "median"
                   and r["status"] == "not_run"]
        if skipped:
            notes.append(f"{t}: not run for n = {', '.join(skipped)} "
                         "(a smaller n was already over the limit)")
    ax.axhline(limit, color="gray", linestyle=":", linewidth=1)
    ax.axhline(1.0, color="green", linestyle="--", linewidth=0.8, alpha=0.6)
    ax.text(8, 1.1, "1 s", color="green", fontsize=8)
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ns = sorted({int(r["n"]) for r in rows})
    ax.set_xticks(ns)
    ax.set_xticklabels([str(n) for n in ns])
    ax.set_ylim(top=limit * 3)
    ax.set_xlabel("n  (rot(2\u03c0/n) composed n times, then exact test == I)")
    ax.set_ylabel("seconds (wall, one run)")
    ax.set_title("Exact rotation composition: Cyclotomic vs CORE")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="center right")
    if notes:
        fig.text(0.01, 0.01, "\n".join(notes), fontsize=7, color="dimgray", va="bottom")
    fig.tight_layout(rect=(0, 0.04 * len(notes), 1, 1))
    fig.savefig(png_path, dpi=120)
    print(f"wrote {png_path}")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_rotation_composition.py CSV PNG")
    main(sys.argv[1], sys.argv[2])
