#!/usr/bin/env bash
# Runs bench_lemma42_ngon (the Lemma 4.2 check of an n-gon slice structure with the exact core)
# for K_m (cyclotomic) and CORE side by side in one run and writes
#   $OUT_DIR/$NAME.csv      every repeat, then one `repeat = median` row per kernel and n
#   $OUT_DIR/$NAME.png      bench/plot_lemma42_ngon.py (if matplotlib is there)
#   $OUT_DIR/$NAME.run.txt  when, where and how the run was made (command, limits, load)
# and prints the median table (markdown) for docs/benchmarks/cyclotomic-vs-core.md.
#
# Usage: bench/run_lemma42_ngon.sh [BINARY] [OUT_DIR]
# Environment:
#   NS ("8 16 32 64 128"), KERNELS ("cyclotomic core"; cyclotomic_lazy is optional),
#   REPEATS (3), NAME (lemma42_ngon),
#   CYCLOTOMIC_NS, CORE_NS, CYCLOTOMIC_LAZY_NS (default NS): the n run for that kernel,
#   CORE_LIMIT_SECONDS (30)              time box of one CORE run,
#   CYCLOTOMIC_LIMIT_SECONDS (120)       time box of one K_m run,
#   CYCLOTOMIC_LAZY_LIMIT_SECONDS (120)  time box of one Lazy_exact_nt<K_m> run,
#   MEMORY_LIMIT_MB (4096)               address-space limit of one run.
# Time boxing (keeps `make bench` short; every skip is recorded as status not_run with a note):
#   * a run over its limit is killed: seconds = limit, status = timeout ("> limit");
#   * once more than half of the REPEATS of (kernel, n) timed out, the median is "> limit"
#     whatever the remaining repeats give, so they are not run;
#   * once the median of (kernel, n) is "> limit", or most repeats failed (status error: the
#     child died, e.g. out of memory under MEMORY_LIMIT_MB, or timed out), that kernel is not
#     run for larger n.
# A wrong answer (Lemma 4.2 verdict not "holds", or wrong counts) makes the binary exit 1, and
# this script with it (set -e, pipefail): no CSV is written.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BIN="${1:-$HERE/../build-bench/bench/bench_lemma42_ngon}"
OUT_DIR="${2:-$HERE/../docs/benchmarks}"
NS="${NS:-8 16 32 64 128}"
KERNELS="${KERNELS:-cyclotomic core}"
CYCLOTOMIC_NS="${CYCLOTOMIC_NS:-$NS}"
CORE_NS="${CORE_NS:-$NS}"
CYCLOTOMIC_LAZY_NS="${CYCLOTOMIC_LAZY_NS:-$NS}"
REPEATS="${REPEATS:-3}"
NAME="${NAME:-lemma42_ngon}"
CORE_LIMIT_SECONDS="${CORE_LIMIT_SECONDS:-30}"
CYCLOTOMIC_LIMIT_SECONDS="${CYCLOTOMIC_LIMIT_SECONDS:-120}"
CYCLOTOMIC_LAZY_LIMIT_SECONDS="${CYCLOTOMIC_LAZY_LIMIT_SECONDS:-120}"
MEMORY_LIMIT_MB="${MEMORY_LIMIT_MB:-4096}"

mkdir -p "$OUT_DIR"
CSV="$OUT_DIR/$NAME.csv"
RUN_TXT="$OUT_DIR/$NAME.run.txt"
RAW="$(mktemp)"
trap 'rm -f "$RAW"' EXIT

# Per-kernel settings: cyclotomic_lazy + NS -> $CYCLOTOMIC_LAZY_NS, etc.
setting() { # kernel suffix
  local v
  v="$(echo "$1" | tr '[:lower:]' '[:upper:]')_$2"
  case "$v" in CORE_* | CYCLOTOMIC_* | CYCLOTOMIC_LAZY_*) ;; *) echo "unknown kernel $1" >&2; exit 2 ;; esac
  echo "${!v}"
}
kernel_runs_n() { # kernel n
  case " $(setting "$1" NS) " in *" $2 "*) return 0 ;; esac
  return 1
}
limit_of() { setting "$1" LIMIT_SECONDS; }
for kernel in $KERNELS; do setting "$kernel" NS >/dev/null; done

START_DATE="$(date -u '+%Y-%m-%d %H:%M:%S UTC')"
START_LOAD="$(uptime)"
START_S=$SECONDS
echo "lemma42_ngon: start $START_DATE; $START_LOAD" >&2

HEADER="n,kernel,repeat,seconds,status,verdict,pairs_checked,vertices,triangles,seconds_transformations,seconds_apply_template,seconds_lemma42,limit_seconds,note"
echo "$HEADER" >"$RAW"
declare -A over_at # kernel -> why larger n are not run ("n = 16 already > limit")
for n in $NS; do
  for kernel in $KERNELS; do
    kernel_runs_n "$kernel" "$n" || continue
    limit="$(limit_of "$kernel")"
    if [ -n "${over_at[$kernel]:-}" ]; then
      for r in $(seq 1 "$REPEATS"); do
        echo "$n,$kernel,$r,,not_run,,,,,,,,$limit,${over_at[$kernel]}" \
          | tee -a "$RAW"
      done
      continue
    fi
    timeouts=0
    errors=0
    for r in $(seq 1 "$REPEATS"); do
      if [ $((2 * timeouts)) -gt "$REPEATS" ]; then
        echo "$n,$kernel,$r,,not_run,,,,,,,,$limit,median already > limit" | tee -a "$RAW"
        continue
      fi
      line="$("$BIN" --kernel "$kernel" --n "$n" --repeats 1 --first-repeat "$r" \
        --limit-seconds "$limit" --memory-limit-mb "$MEMORY_LIMIT_MB")"
      echo "$line,$limit," | tee -a "$RAW"
      case "$line" in
        *,timeout,*) timeouts=$((timeouts + 1)) ;;
        *,error,*) errors=$((errors + 1)) ;;
      esac
    done
    if [ $((2 * timeouts)) -gt "$REPEATS" ]; then
      over_at[$kernel]="n = $n already > limit"
    elif [ $((2 * (timeouts + errors))) -gt "$REPEATS" ]; then
      over_at[$kernel]="n = $n already failed (error/timeout)"
    fi
  done
done

# Medians over the REPEATS planned repeats: a timeout counts as its limit (a lower bound) and a
# repeat skipped because the median was already over counts as over the limit too; a median
# that is such a value is status timeout ("> limit"). Errors are left out.
/usr/bin/python3 - "$RAW" "$CSV" "$REPEATS" <<'PY'
import csv, sys
raw, out, repeats = sys.argv[1], sys.argv[2], int(sys.argv[3])
rows = list(csv.DictReader(open(raw)))
fields = list(rows[0].keys()) if rows else []
with open(out, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow(r)
    keys = []
    for r in rows:
        if (r["n"], r["kernel"]) not in keys:
            keys.append((r["n"], r["kernel"]))
    for n, k in keys:
        rs = [r for r in rows if r["n"] == n and r["kernel"] == k]
        base = {"n": n, "kernel": k, "repeat": "median", "limit_seconds": rs[0]["limit_seconds"]}
        if all(r["status"] == "not_run" and r["note"].startswith("n = ") for r in rs):
            w.writerow({**base, "status": "not_run", "note": rs[0]["note"]})
            continue
        limit = float(rs[0]["limit_seconds"])
        vals = []  # (seconds, over_limit, row)
        for r in rs:
            if r["status"] == "ok":
                vals.append((float(r["seconds"]), False, r))
            elif r["status"] in ("timeout", "not_run"):
                vals.append((limit, True, r))
        errs = [float(r["seconds"]) for r in rs if r["status"] == "error" and r["seconds"]]
        err_note = (f"{len(errs)} of {len(rs)} repeats died (error) after "
                    f"{min(errs):.0f}-{max(errs):.0f} s" if errs else "")
        if not vals:
            w.writerow({**base, "status": "error", "note": err_note or "every repeat failed"})
            continue
        vals.sort(key=lambda v: (v[0], v[1]))
        if len(vals) % 2:
            s, over, r = vals[(len(vals) - 1) // 2]
        else:
            a, b = vals[len(vals) // 2 - 1], vals[len(vals) // 2]
            s, over, r = (a[0] + b[0]) / 2, a[1] or b[1], b[2]
        ran = sum(1 for r2 in rs if r2["status"] in ("ok", "timeout", "error"))
        to = sum(1 for r2 in rs if r2["status"] == "timeout")
        note = f"{ran} of {len(rs)} repeats run, {to} timed out" if (to or ran < len(rs)) else ""
        note = "; ".join(x for x in (note, err_note) if x)
        if over:
            w.writerow({**base, "seconds": f"{limit:.6f}", "status": "timeout", "note": note})
        else:
            w.writerow({**base, "seconds": f"{s:.6f}", "status": "ok", "verdict": r["verdict"],
                        "pairs_checked": r["pairs_checked"], "vertices": r["vertices"],
                        "triangles": r["triangles"],
                        "seconds_transformations": r["seconds_transformations"],
                        "seconds_apply_template": r["seconds_apply_template"],
                        "seconds_lemma42": r["seconds_lemma42"], "note": note})
PY
echo "wrote $CSV" >&2

if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "$HERE/plot_lemma42_ngon.py" "$CSV" "$OUT_DIR/$NAME.png"
else
  echo "matplotlib missing (python3-matplotlib, scripts/install-deps.sh): no plot" >&2
fi

END_LOAD="$(uptime)"
{
  echo "benchmark: bench_lemma42_ngon (bench/lemma42_ngon.cpp), driver bench/run_lemma42_ngon.sh"
  settings=""
  for kernel in $KERNELS; do
    up="$(echo "$kernel" | tr '[:lower:]' '[:upper:]')"
    settings+="${up}_NS=\"$(setting "$kernel" NS)\" ${up}_LIMIT_SECONDS=$(limit_of "$kernel") "
  done
  echo "command: NS=\"$NS\" KERNELS=\"$KERNELS\" ${settings}REPEATS=$REPEATS MEMORY_LIMIT_MB=$MEMORY_LIMIT_MB NAME=$NAME bash bench/run_lemma42_ngon.sh $BIN $OUT_DIR"
  echo "started: $START_DATE"
  echo "wall time of the whole run: $((SECONDS - START_S)) s"
  echo "uptime at start: $START_LOAD"
  echo "uptime at end:   $END_LOAD"
  echo "source: git HEAD $(git -C "$HERE/.." rev-parse --short HEAD 2>/dev/null || echo unknown)," \
    "uncommitted changes under src/: $(git -C "$HERE/.." status --porcelain -- src 2>/dev/null | wc -l) files"
  echo "nproc: $(nproc)"
  echo "cpu: $(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1)"
  echo "kernel: $(uname -sr)"
  echo "compiler: $(c++ --version 2>/dev/null | head -1)"
} >"$RUN_TXT"
echo "wrote $RUN_TXT" >&2

# Median table (markdown) for docs/benchmarks/cyclotomic-vs-core.md.
/usr/bin/python3 "$HERE/plot_lemma42_ngon.py" --table "$CSV"
