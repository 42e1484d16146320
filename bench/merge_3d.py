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
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from generate_2d import commit, cpu_model  # noqa: E402
import merge_common  # noqa: E402

OBJECTS = [("cube-halves", (0.3, 0.15)), ("finfet", (0.3, 0.15)), ("tsv-8", (0.3, 0.15)),
           ("tsv-32", (0.3, 0.15)), ("multi-tsv", (0.3,))]
LOAD = os.getloadavg()[0]


def summarise(rows, outdir, wall, argv, repeats):
    table = merge_common.medians(rows, "auto", "min_dihedral_deg")
    merge_common.plot(table, os.path.join(outdir, "merge_3d.png"),
                      [f"{t['object']}\nh={t['size']:g}" for t in table], "Alg. 5.7 (auto)",
                      "smallest dihedral angle of AT, degrees", (11, 4.5), 7)
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
            f"| {t['object']} | {t['size']:g} | {t['reference']} | {t['cells_ref']} / "
            f"{t['cells_merge']} | {t['merged']} / {t['inserted']} | {t['gen_ref']:.3f} / "
            f"{t['gen_merge']:.3f} | {t['cert_ref']:.3f} / {t['cert_merge']:.3f} | {t['wall_ref']:.3f} / "
            f"{t['wall_merge']:.3f} ({t['wall_merge'] / t['wall_ref']:.2f}) | {t['rss_ref'] / 2**20:.0f} / "
            f"{t['rss_merge'] / 2**20:.0f} | {t['quality_ref']:.1f} / {t['quality_merge']:.1f} |")
    ratios = [t["wall_merge"] / t["wall_ref"] for t in table]
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
                     f"overlay points; smallest dihedral {t['quality_ref']:.1f}° → {t['quality_merge']:.1f}°)"
                     for t in changed) if changed else "none") + ".",
        "- Where the faces that meet see the same 2D input in their own frames (the TSV slices' "
        "interfaces, the cube halves' mirror face), independent meshing gives the same "
        "triangulation and the merge has nothing to do; its cost is then meshing every face "
        "instead of one per class.",
        ""]
    open(os.path.join(outdir, "merge_3d.md"), "w").write("\n".join(lines))


def main():
    # The commit as the run starts: the run's own outputs would otherwise mark it dirty.
    import generate_2d
    generate_2d.STARTED_AT = commit()
    ap = argparse.ArgumentParser()
    ap.add_argument("symmesh")
    ap.add_argument("outdir")
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    start = time.time()
    with tempfile.TemporaryDirectory() as tmp:
        cases = []
        for name, sizes in OBJECTS:
            geometry = os.path.join(tmp, name + ".json")
            subprocess.run([a.symmesh, "example", name, "-o", geometry], check=True)
            cases.append((name, geometry, sizes))
        rows = merge_common.measure(a.symmesh, cases, ("auto", "merge"), a.repeats, tmp, (),
                                    "min_dihedral_deg")
    merge_common.write_csv(os.path.join(a.outdir, "merge_3d.csv"), "min_dihedral_deg", rows)
    summarise(rows, a.outdir, time.time() - start, ["bench/merge_3d.py"] + sys.argv[1:], a.repeats)


if __name__ == "__main__":
    main()
