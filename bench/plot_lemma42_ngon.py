#!/usr/bin/python3
"""Plot or tabulate docs/benchmarks/lemma42_ngon.csv (bench/run_lemma42_ngon.sh).

Usage: plot_lemma42_ngon.py CSV PNG     median time vs n (log-log), both kernels
       plot_lemma42_ngon.py --table CSV  the median table (markdown) on stdout

Timeouts are drawn at their limit with an upward triangle ("> limit"); kernels not run for an n
(a smaller n was already over the limit) are not drawn, only noted. Each finished repeat is a
small dot behind the median line. The table gives the phases (transformations, AT, Lemma 4.2
checker) of the median K_m run.
"""
import csv
import sys

KERNELS = {
    "cyclotomic": ("tab:blue", "o", "Cyclotomic K_lcm(4,n) (symmesh)"),
    "core": ("tab:red", "s", "CORE::Expr (Epeck_with_sqrt)"),
    "cyclotomic_lazy": ("tab:green", "D", "Lazy_exact_nt<Cyclotomic> (interval filter)"),
}


def medians(rows, kernel):
    return sorted((r for r in rows if r["kernel"] == kernel and r["repeat"] == "median"),
                  key=lambda r: int(r["n"]))


def field_degree(n):
    from math import gcd
    m = 4 * n // gcd(4, n)
    phi = sum(1 for k in range(1, m + 1) if gcd(k, m) == 1)
    return m, max(phi // 2, 1)


def table(csv_path):
    rows = list(csv.DictReader(open(csv_path)))
    med = [r for r in rows if r["repeat"] == "median"]
    ns = sorted({int(r["n"]) for r in med})

    def get(kernel, n):
        for r in med:
            if r["kernel"] == kernel and int(r["n"]) == n:
                return r
        return None

    def cell(r):
        if r is None:
            return "-"
        lim = float(r["limit_seconds"])
        if r["status"] == "ok":
            return f"{float(r['seconds']):.3f} s ({r['verdict']})"
        if r["status"] == "timeout":
            return f"> {lim:g} s (timeout; {r['note']})"
        if r["status"] == "not_run":
            return f"not run ({r['note']})"
        return f"error ({r['note']})" if r["note"] else "error"

    def ratio(k, c):
        if k is None or c is None:
            return "-"
        if k["status"] == "ok" and c["status"] == "ok":
            return f"{float(c['seconds']) / float(k['seconds']):.2g}×"
        if k["status"] == "ok" and c["status"] == "timeout":
            return f"> {float(c['limit_seconds']) / float(k['seconds']):.3g}×"
        if c["status"] == "ok" and k["status"] == "timeout":
            return f"< {float(c['seconds']) / float(k['limit_seconds']):.3g}×"
        return "- (not measured)"

    def phases(r):
        if r is None or r["status"] != "ok":
            return "-"
        return (f"{float(r['seconds_transformations']):.3f} / "
                f"{float(r['seconds_apply_template']):.3f} / {float(r['seconds_lemma42']):.3f}")

    lazy = any(r["kernel"] == "cyclotomic_lazy" for r in med)
    print("| n | pairs | K_m (d) | Cyclotomic K_m | CORE (Epeck_with_sqrt) | CORE / K_m "
          + ("| Lazy_exact_nt<K_m> | K_m / lazy " if lazy else "")
          + "| K_m phases: transf. / AT / Lemma 4.2 (s) |")
    print("|---:|---:|---|---|---|---:|" + ("---|---:|" if lazy else "") + "---|")
    for n in ns:
        k, c, z = get("cyclotomic", n), get("core", n), get("cyclotomic_lazy", n)
        m, d = field_degree(n)
        extra = f"| {cell(z)} | {ratio(z, k)} " if lazy else ""
        print(f"| {n} | {n * (n - 1) // 2} | K_{m} ({d}) | {cell(k)} | {cell(c)} | {ratio(k, c)} "
              f"{extra}| {phases(k)} |")


def plot(csv_path, png_path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = list(csv.DictReader(open(csv_path)))
    limits = [float(r["limit_seconds"]) for r in rows if r["limit_seconds"]]
    top = max(limits) if limits else 60.0
    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    notes = []
    drawn = False
    for kernel, (color, marker, label) in KERNELS.items():
        med = [r for r in medians(rows, kernel) if r["status"] in ("ok", "timeout")]
        if not med and not any(r["kernel"] == kernel for r in rows):
            continue
        reps = [r for r in rows if r["kernel"] == kernel and r["repeat"] != "median"
                and r["status"] == "ok"]
        ax.scatter([int(r["n"]) for r in reps], [max(float(r["seconds"]), 1e-6) for r in reps],
                   color=color, s=8, alpha=0.4)
        xs = [int(r["n"]) for r in med]
        ys = [max(float(r["seconds"]), 1e-6) for r in med]
        for (x0, y0, r0), (x1, y1, r1) in zip(zip(xs, ys, med), list(zip(xs, ys, med))[1:]):
            dotted = "timeout" in (r0["status"], r1["status"])
            ax.plot([x0, x1], [y0, y1], color=color, linestyle=":" if dotted else "-", alpha=0.7)
        ok = [r for r in med if r["status"] == "ok"]
        to = [r for r in med if r["status"] == "timeout"]
        drawn = drawn or bool(med)
        ax.plot([int(r["n"]) for r in ok], [max(float(r["seconds"]), 1e-6) for r in ok],
                linestyle="none", marker=marker, color=color, label=label + " (median)")
        if to:
            ax.plot([int(r["n"]) for r in to], [float(r["seconds"]) for r in to],
                    linestyle="none", marker="^", markersize=10, color=color,
                    label=f"{kernel}: > limit (killed)")
            for r in to:
                ax.annotate(f"> {float(r['seconds']):g} s", (int(r["n"]), float(r["seconds"])),
                            textcoords="offset points", xytext=(0, 8), ha="center",
                            fontsize=8, color=color)
        for r in medians(rows, kernel):
            if r["status"] == "error":
                notes.append(f"{kernel}: n = {r['n']} failed: {r['note'] or 'error'}")
        skipped = [int(r["n"]) for r in medians(rows, kernel) if r["status"] == "not_run"]
        if skipped:
            notes.append(f"{kernel}: not run for n = {', '.join(map(str, skipped))} "
                         f"(smaller n already over its limit)")
    for lim in sorted(set(limits)):
        ax.axhline(lim, color="gray", linestyle=":", linewidth=1)
    ax.set_xscale("log", base=2)
    if drawn:
        ax.set_yscale("log")
    else:
        ax.text(0.5, 0.5, "no run finished or timed out", transform=ax.transAxes, ha="center")
    ns = sorted({int(r["n"]) for r in rows})
    ax.set_xlim(min(ns) / 1.3, max(ns) * 1.3)
    ax.set_xticks(ns)
    ax.set_xticklabels([str(n) for n in ns])
    ax.set_ylim(top=top * 4)
    ax.set_xlabel("n  (wedge of angle 2\u03c0/n instanced n times; C(n,2) neighbouring pairs)")
    ax.set_ylabel("seconds (wall, one run)")
    ax.set_title("Lemma 4.2 check of an n-gon slice structure: K_m vs CORE")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    if notes:
        fig.text(0.01, 0.01, "\n".join(notes), fontsize=7, color="dimgray", va="bottom")
    fig.tight_layout(rect=(0, 0.04 * len(notes), 1, 1))
    fig.savefig(png_path, dpi=120)
    print(f"wrote {png_path}", file=sys.stderr)


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--table":
        table(sys.argv[2])
    elif len(sys.argv) == 3:
        plot(sys.argv[1], sys.argv[2])
    else:
        sys.exit("usage: plot_lemma42_ngon.py CSV PNG | plot_lemma42_ngon.py --table CSV")
