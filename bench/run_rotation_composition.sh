#!/usr/bin/env bash
# Runs bench_rotation_composition for cyclotomic and CORE side by side in one run and writes
#   $OUT_DIR/cyclotomic_vs_core.csv  (every repeat, then one median row per type and n)
#   $OUT_DIR/cyclotomic_vs_core.png  (bench/plot_rotation_composition.py, if matplotlib is there)
#
# Usage: bench/run_rotation_composition.sh [BINARY] [OUT_DIR]
# Environment: LIMIT_SECONDS (60) time box of one CORE/cyclotomic run, REPEATS (3),
#              NS ("8 16 32 64 128"), MEMORY_LIMIT_MB (4096) address-space limit of one run,
#              SKIP_AFTER_TIMEOUT (1; 0 runs every repeat of every n).
# A run that exceeds LIMIT_SECONDS is killed and recorded with seconds = LIMIT_SECONDS,
# status = timeout ("> limit"); a median row is a timeout when the median repeat is one.
# With SKIP_AFTER_TIMEOUT=1 (keeps `make bench` short), once more than half of the repeats of
# (type, n) timed out the remaining ones are not run (the median is "> limit" whatever they
# give), and a type whose median timed out is not run for larger n; such rows have
# status = not_run and are reported as such.
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
BIN="${1:-$HERE/../build-bench/bench/bench_rotation_composition}"
OUT_DIR="${2:-$HERE/../docs/benchmarks}"
LIMIT_SECONDS="${LIMIT_SECONDS:-60}"
REPEATS="${REPEATS:-3}"
NS="${NS:-8 16 32 64 128}"
MEMORY_LIMIT_MB="${MEMORY_LIMIT_MB:-4096}"
SKIP_AFTER_TIMEOUT="${SKIP_AFTER_TIMEOUT:-1}"

mkdir -p "$OUT_DIR"
CSV="$OUT_DIR/cyclotomic_vs_core.csv"
RAW="$(mktemp)"
trap 'rm -f "$RAW"' EXIT

echo "type,n,repeat,seconds,is_identity,status" >"$RAW"
declare -A over_at # type -> the n whose median was over the limit
for n in $NS; do
  for type in cyclotomic core; do
    if [ -n "${over_at[$type]:-}" ]; then
      for r in $(seq 1 "$REPEATS"); do
        echo "$type,$n,$r,,,not_run" | tee -a "$RAW"
      done
      continue
    fi
    timeouts=0
    for r in $(seq 1 "$REPEATS"); do
      if [ "$SKIP_AFTER_TIMEOUT" = 1 ] && [ $((2 * timeouts)) -gt "$REPEATS" ]; then
        echo "$type,$n,$r,,,not_run" | tee -a "$RAW"
        continue
      fi
      line="$("$BIN" --type "$type" --n "$n" --repeats 1 --first-repeat "$r" \
        --limit-seconds "$LIMIT_SECONDS" --memory-limit-mb "$MEMORY_LIMIT_MB")"
      echo "$line" | tee -a "$RAW"
      case "$line" in *,timeout) timeouts=$((timeouts + 1)) ;; esac
    done
    if [ "$SKIP_AFTER_TIMEOUT" = 1 ] && [ $((2 * timeouts)) -gt "$REPEATS" ]; then
      over_at[$type]=$n
    fi
  done
done

# Medians: timeouts count as LIMIT_SECONDS (a lower bound), errors are left out.
/usr/bin/python3 - "$RAW" "$CSV" "$LIMIT_SECONDS" <<'PY'
import csv, sys
raw, out, limit = sys.argv[1], sys.argv[2], float(sys.argv[3])
rows = list(csv.DictReader(open(raw)))
fields = ["type", "n", "repeat", "seconds", "is_identity", "status", "limit_seconds"]
with open(out, "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=fields, lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow({**r, "limit_seconds": f"{limit:g}"})
    keys = []
    for r in rows:
        if (r["type"], r["n"]) not in keys:
            keys.append((r["type"], r["n"]))
    for t, n in keys:
        all_rs = [r for r in rows if r["type"] == t and r["n"] == n]
        if all(r["status"] == "not_run" for r in all_rs):  # a smaller n was already over
            w.writerow({"type": t, "n": n, "repeat": "median", "status": "not_run",
                        "limit_seconds": f"{limit:g}"})
            continue
        # A repeat skipped because the median was already over the limit counts as over it.
        rs = [dict(r, seconds=f"{limit:.6f}", status="timeout") if r["status"] == "not_run"
              else r for r in all_rs if r["status"] != "error"]
        rs.sort(key=lambda r: (float(r["seconds"]), r["status"] == "timeout"))
        if not rs:
            w.writerow({"type": t, "n": n, "repeat": "median", "status": "error",
                        "limit_seconds": f"{limit:g}"})
            continue
        m = rs[(len(rs) - 1) // 2] if len(rs) % 2 else None
        if m is None:  # even count: mean of the two middle repeats, timeout if either is
            a, b = rs[len(rs) // 2 - 1], rs[len(rs) // 2]
            status = "timeout" if "timeout" in (a["status"], b["status"]) else "ok"
            ident = a["is_identity"] if a["is_identity"] == b["is_identity"] else ""
            m = {"seconds": f"{(float(a['seconds']) + float(b['seconds'])) / 2:.6f}",
                 "is_identity": ident, "status": status}
        w.writerow({"type": t, "n": n, "repeat": "median", "seconds": m["seconds"],
                    "is_identity": m["is_identity"], "status": m["status"],
                    "limit_seconds": f"{limit:g}"})
PY
echo "wrote $CSV"

if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "$HERE/plot_rotation_composition.py" "$CSV" "$OUT_DIR/cyclotomic_vs_core.png"
else
  echo "matplotlib missing (python3-matplotlib, scripts/install-deps.sh): no plot" >&2
fi

# Median table (markdown) for docs/benchmarks/cyclotomic-vs-core.md.
/usr/bin/python3 - "$CSV" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["repeat"] == "median"]
ns = sorted({int(r["n"]) for r in rows})
def cell(t, n):
    for r in rows:
        if r["type"] == t and int(r["n"]) == n:
            if r["status"] == "timeout":
                return f"> {float(r['limit_seconds']):g} s (timeout)"
            if r["status"] == "not_run":
                return "not run (a smaller n was already over the limit)"
            if r["status"] == "error":
                return "error"
            return f"{float(r['seconds']):.4f} s ({'identity' if r['is_identity'] == 'true' else 'NOT identity'})"
    return "-"
def ratio(n):
    k = [r for r in rows if r["type"] == "cyclotomic" and int(r["n"]) == n]
    c = [r for r in rows if r["type"] == "core" and int(r["n"]) == n]
    if not k or not c or k[0]["status"] != "ok":
        return "-"
    if c[0]["status"] == "ok":
        return f"{float(c[0]['seconds']) / float(k[0]['seconds']):.0f}×"
    if c[0]["status"] == "timeout":
        return f"> {float(c[0]['limit_seconds']) / float(k[0]['seconds']):.0f}×"
    return "-"
print("| n | Cyclotomic (K_lcm(4,n)) | CORE (Epeck_with_sqrt) | CORE / Cyclotomic (medians) |")
print("|---:|---|---|---:|")
for n in ns:
    print(f"| {n} | {cell('cyclotomic', n)} | {cell('core', n)} | {ratio(n)} |")
PY
