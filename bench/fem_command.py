#!/usr/bin/python3
"""The whole `symmesh solve` command, TCSR vs CSR (issue 17; docs/benchmarks/fem_command.md).

The in-process matrix-vector products of fem.md are not what a user waits for. Here the whole
command — read the .tmesh, assemble, apply the boundary conditions, CG with Jacobi to rtol 1e-6,
write the .vtu — runs with `--solver tcsr` and with `--solver csr` (the same command, the operator
converted to CSR by Algorithm 7.1 before CG), side by side, repeats interleaved; wall time from
outside the process, peak RSS from the command's report. The n-gon slices at about 1e6 unknowns.

Usage: fem_command.py SYMMESH OUTDIR [--repeats R]
"""
import argparse
import json
import math
import os
import platform
import statistics
import subprocess
import sys
import tempfile
import time

H_1E6 = 0.0025 * math.sqrt(1.2176)  # about 1e6 unknowns on every n-gon slice structure


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("symmesh")
    ap.add_argument("out")
    ap.add_argument("--repeats", type=int, default=3)
    args = ap.parse_args()
    tmp = tempfile.mkdtemp()
    bc = os.path.join(tmp, "bc.json")
    json.dump({"symmesh": "boundary-conditions/1", "source": 1,
               "dirichlet": [{"on": {}, "value": 0}]}, open(bc, "w"))
    rows = []
    start = time.time()
    for n in (16, 128):
        geometry = os.path.join(tmp, "g.json")
        tmesh = os.path.join(tmp, "m%d.tmesh" % n)
        subprocess.run([args.symmesh, "example", "ngon-slice-%d" % n, "-o", geometry], check=True)
        subprocess.run([args.symmesh, "generate", geometry, "--size", "%.6g" % H_1E6,
                        "--templated", tmesh, "--quiet"], check=True)
        runs = {"tcsr": [], "csr": []}
        for _ in range(args.repeats):
            for solver in ("tcsr", "csr"):
                report = os.path.join(tmp, "r.json")
                cmd = [args.symmesh, "solve", tmesh, "--bc", bc, "--solver", solver,
                       "--ksp-rtol", "1e-6", "-o", os.path.join(tmp, "u.vtu"), "--report", report,
                       "--quiet"]
                t0 = time.perf_counter()
                subprocess.run(cmd, check=True)
                wall = time.perf_counter() - t0
                r = json.load(open(report))
                runs[solver].append((wall, r["peak_rss_bytes"], r["unknowns"], r["iterations"],
                                     r["seconds_solve"]))
        row = {"n": n, "unknowns": runs["tcsr"][0][2], "iterations": runs["tcsr"][0][3]}
        for s in runs:
            row[s + "_wall"] = statistics.median(x[0] for x in runs[s])
            row[s + "_solve"] = statistics.median(x[4] for x in runs[s])
            row[s + "_rss"] = max(x[1] for x in runs[s])
        rows.append(row)
        print("n = %d: whole command CSR/TCSR %.2f, peak RSS %.0f / %.0f MiB" % (
            n, row["csr_wall"] / row["tcsr_wall"], row["csr_rss"] / 2**20,
            row["tcsr_rss"] / 2**20), file=sys.stderr)
    md = ["# The whole `symmesh solve` command: TCSR vs CSR", "",
          "Written by `bench/fem_command.py` (run by `make bench`). Machine: %s, %d cores. "
          "Command: `%s`. Wall time: %.0f s. Medians of %d runs, interleaved (tcsr, csr, tcsr, …); "
          "wall time measured outside the process (read .tmesh, assemble per template, boundary "
          "conditions, CG with Jacobi to rtol 1e-6, write .vtu); peak RSS from the report. Each run: "
          "`symmesh solve M.tmesh --bc BC.json --solver S --ksp-rtol 1e-6 -o u.vtu --report R.json "
          "--quiet` with S = tcsr or csr, BC: u = 0 on the whole boundary, source 1; M from "
          "`symmesh generate ngon-slice-n.json --size %.6g --templated M.tmesh`." % (
              platform.node(), os.cpu_count(), " ".join(["python3"] + sys.argv),
              time.time() - start, args.repeats, H_1E6), "",
          "| n | unknowns | CG iterations | TCSR s | CSR s | CSR/TCSR | TCSR solve s | "
          "CSR solve s | TCSR peak RSS MiB | CSR peak RSS MiB |", "|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append("| %d | %d | %d | %.2f | %.2f | %.2f | %.2f | %.2f | %.0f | %.0f |" % (
            r["n"], r["unknowns"], r["iterations"], r["tcsr_wall"], r["csr_wall"],
            r["csr_wall"] / r["tcsr_wall"], r["tcsr_solve"], r["csr_solve"], r["tcsr_rss"] / 2**20,
            r["csr_rss"] / 2**20))
    md += ["", "The CSR run builds the TCSR first and converts it (Algorithm 7.1), so its peak RSS "
           "holds both; both read the same templated mesh. The product's own ratio is in fem.md."]
    open(os.path.join(args.out, "fem_command.md"), "w").write("\n".join(md) + "\n")


if __name__ == "__main__":
    main()
