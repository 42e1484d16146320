#!/usr/bin/env bash
# Builds the fuzz harnesses with clang-14 (libFuzzer + ASan + UBSan, the library instrumented too)
# and runs a time-boxed campaign per harness, each starting from its saved corpus
# (fuzz/corpus/<harness>/, which `make test` replays). Writes docs/fuzzing.md: executions,
# coverage (libFuzzer's cov: edges) and findings per harness, with the machine and the command.
# Usage: [FUZZ_PARALLEL=1] [FUZZ_WORKERS=N] bash fuzz/run.sh [seconds per harness] [harness...]
# (default 120, all six; FUZZ_PARALLEL=1 runs them side by side; FUZZ_WORKERS=N runs N processes
# per harness on one shared corpus, as libFuzzer's -jobs does; FUZZ_REPORT_ONLY=1 only rewrites
# the report).
# Findings go to build-fuzz/<harness>/{crash,timeout,oom}-*; copy each into fuzz/corpus/<harness>/
# once fixed, so that it stays a regression test. Under ASan+UBSan an input costs ~15x its
# Release time; -timeout=60 flags only real hangs.
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-120}
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(templated_structure_json tmesh generate adapt tmesh_cloning delaunay_3d)
report=docs/fuzzing.md
# A timeout is wall-clock time: a niced campaign beside a build can be starved past it. Each
# timeout input is run again alone; one that ends within the limit is kept as
# unreproduced-timeout-* and not counted as a finding.
confirm_timeouts() {
  local h=$1 f
  for f in build-fuzz/"$h"/timeout-*; do
    [ -e "$f" ] || continue
    if ASAN_OPTIONS=malloc_context_size=0 timeout 300 ./build-fuzz/fuzz/fuzz_"$h" "$f" \
        -timeout=60 > /dev/null 2>&1; then
      mv "$f" "build-fuzz/$h/unreproduced-${f##*/}"
    fi
  done
}
# Every finished campaign is one line of fuzz/campaigns.csv (kept in git): the harness, the
# SHA-256 of its source when the campaign started, when its log ended, seconds, executions,
# coverage and findings. A campaign is recorded once (by harness and log time), also when
# FUZZ_REPORT_ONLY=1 reads its log again. The report sums the campaigns of each harness's
# current source: executions of the same checks, possibly over a library that changed between
# campaigns (each campaign starts from the saved inputs of the one before).
campaigns=fuzz/campaigns.csv
harness_sha() { sha256sum "fuzz/fuzz_$1.cpp" | cut -c1-12; }
record_campaign() {
  local h=$1 work=build-fuzz/$1 sha ended
  # A campaign run before run.sh kept harness.sha has no known source: "unknown".
  sha=$(cat "$work/harness.sha" 2>/dev/null || echo unknown)
  ended=$(date -u -d "@$(stat -c %Y "$work/campaign.log")" +%Y-%m-%dT%H:%M:%SZ)
  [ -f "$campaigns" ] || echo "harness,harness_sha256,ended_utc,seconds,executions,coverage,findings,processes" > "$campaigns"
  grep -q "^$h,[0-9a-f]*,$ended," "$campaigns" && return 0
  echo "$h,$sha,$ended,${2// /_},$3,$4,$5,$6" >> "$campaigns"
}
# The row of a harness from its campaign logs (campaign.log, and campaign.wK.log for the workers
# K = 2..N): the wall seconds it ran (the given ones, or executions / average rate when findings
# stopped every process early), executions summed over the processes, coverage (the largest of
# theirs: they share one corpus), corpus size and findings.
write_row() {
  local h=$1 day=$2 work=build-fuzz/$1
  confirm_timeouts "$h"
  local runs=0 cov=0 files findings unrepro ran=${3:-$secs} n=0 stopped=0 longest=0 log r a c
  for log in "$work/campaign.log" "$work"/campaign.w*.log; do
    [ -f "$log" ] || continue
    n=$((n + 1))
    r=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1)
    a=$(grep -oE 'stat::average_exec_per_sec: *[0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1)
    c=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | grep -oE '[0-9]+')
    runs=$((runs + ${r:-0}))
    [ "${c:-0}" -le "$cov" ] || cov=$c
    if grep -qE '^SUMMARY: libFuzzer|ERROR: libFuzzer' "$log" && [ "${a:-0}" -gt 0 ]; then
      stopped=$((stopped + 1))
      [ $((r / a)) -le "$longest" ] || longest=$((r / a))
    fi
  done
  [ "$n" -gt 0 ] && [ "$stopped" != "$n" ] || ran="about $longest"
  files=$(ls "$work/corpus" | wc -l)
  findings=$(ls "$work" | grep -cE '^(crash|timeout|oom|leak)-' || true)
  unrepro=$(ls "$work" | grep -cE '^unreproduced-' || true)
  local note=""
  [ "$unrepro" = 0 ] || note=" ($unrepro timeout under load stopped it; alone it ran within the limit)"
  local procs=""
  [ "$n" -le 1 ] || procs=" ($n processes)"
  echo "| $h | $day | $ran$procs | $runs | $cov | $files | $findings$note |" > "$work/row"
  record_campaign "$h" "$ran" "$runs" "$cov" "$findings" "$n"
  echo "fuzz: $h: $runs executions in $n processes, cov $cov, $findings findings$note" >&2
}
# FUZZ_REPORT_ONLY=1 runs nothing: it rewrites the report from the harnesses' last rows
# (build-fuzz/<harness>/row), e.g. after an older run that overlapped this one wrote its own.
if [ "${FUZZ_REPORT_ONLY:-0}" != 1 ]; then
bash scripts/install-deps.sh --fuzz
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DSYMMESH_FUZZ=ON -DSYMMESH_BUILD_TESTS=OFF -DSYMMESH_BUILD_PYTHON=OFF -DSYMMESH_WERROR=OFF
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build build-fuzz -j "$(nproc)" --target "${targets[@]}"
# One campaign; its row goes to build-fuzz/<harness>/row, collected below in the given order.
campaign() {
  local h=$1 work=build-fuzz/$1
  mkdir -p "$work/corpus"
  rm -f "$work"/crash-* "$work"/timeout-* "$work"/oom-* "$work"/leak-* "$work"/unreproduced-* "$work/row"
  rm -f "$work"/campaign.w*.log
  cp fuzz/corpus/"$h"/* "$work/corpus/" 2>/dev/null || true
  harness_sha "$h" > "$work/harness.sha"
  local log=$work/campaign.log
  # The adaptation harness reads 3 bytes per operation: 31 bytes = up to 10 operations; the
  # cloning harness ignores inputs longer than 41 bytes (20 operations), the Technique 5.8 one
  # inputs longer than 24 (6 geometry bytes and 6 operations).
  local max_len=4096
  [ "$h" = adapt ] && max_len=31
  [ "$h" = tmesh_cloning ] && max_len=41
  [ "$h" = delaunay_3d ] && max_len=24
  # Speed: ASan keeps no allocation stacks (a finding is replayed with full stacks from its
  # artifact), and every harness but generate uses the plain scheduler: entropic's feature
  # bookkeeping took 22 % of the JSON harness's time (356 -> 481 inputs/s without it) and 53 % of
  # the adaptation harness's (60 -> 130 inputs/s).
  local extra=()
  [ "$h" = generate ] || extra=(-entropic=0)
  # Workers share the corpus directory: each rereads it and so picks up what the others found.
  # libFuzzer's default rereads it every second, a listing of thousands of files that took 11 % of
  # a JSON process: once a minute for workers, never for a single process.
  local k pids=() reload=0
  [ "${FUZZ_WORKERS:-1}" = 1 ] || reload=60
  set +e
  for ((k = 1; k <= ${FUZZ_WORKERS:-1}; k++)); do
    [ "$k" = 1 ] || log=$work/campaign.w$k.log
    ASAN_OPTIONS=malloc_context_size=0 ./build-fuzz/fuzz/fuzz_"$h" "$work/corpus" \
      -max_total_time="$secs" -max_len="$max_len" -timeout=60 -rss_limit_mb=4096 -reload=$reload \
      -print_final_stats=1 -artifact_prefix="$work/" "${extra[@]}" \
      > "$log" 2>&1 &
    pids+=($!)
  done
  wait "${pids[@]}"
  set -e
  write_row "$h" "$(date -u +%Y-%m-%d)"
}
# FUZZ_PARALLEL=1 runs the campaigns side by side (one core each) instead of one after another.
if [ "${FUZZ_PARALLEL:-0}" = 1 ]; then
  for h in "${harnesses[@]}"; do campaign "$h" & done
  wait
else
  for h in "${harnesses[@]}"; do campaign "$h"; done
fi
fi
# The report is composed when the campaigns end, under a lock, from the report as it is then:
# rows of harnesses not run this time are kept, so that two runs may overlap (each its own
# harnesses) without losing the other's rows.
if [ "${FUZZ_REPORT_ONLY:-0}" = 1 ]; then
  for h in "${harnesses[@]}"; do
    [ -f "build-fuzz/$h/row" ] || continue
    write_row "$h" "$(awk -F'|' '{gsub(/ /, "", $3); print $3}' "build-fuzz/$h/row")" \
      "$(awk -F'|' '{sub(/ \(.*/, "", $4); gsub(/^ +| +$/, "", $4); print $4}' "build-fuzz/$h/row")"
  done
fi
exec 9> build-fuzz/report.lock
flock 9
part=$(mktemp "$report.XXXXXX")
{
  echo "# Fuzzing campaigns"
  echo
  echo "Written by \`bash fuzz/run.sh SECONDS [HARNESS...]\` (clang-14, libFuzzer, ASan + UBSan, the library"
  echo "instrumented; $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')). A row is the"
  echo "latest campaign of its harness, started from its saved inputs. Harnesses: fuzz/*.cpp; saved"
  echo "inputs: fuzz/corpus/<harness>/, replayed by \`make test\` (ctest fuzz.replay_*). A finding is"
  echo "fixed and then saved in the corpus, so that it stays a regression test. A row's campaign ran"
  echo "alone on its core or beside others (FUZZ_PARALLEL=1, or overlapping runs); the machine's other"
  echo "core was not kept idle, so executions per second are lower bounds. \"(N processes)\" marks a"
  echo "campaign of N processes on one shared corpus (FUZZ_WORKERS=N): its seconds are wall seconds, its"
  echo "executions the sum over the processes."
  echo
  echo "| harness | date | seconds | executions | coverage (edges) | corpus | findings |"
  echo "|---|---|---|---|---|---|---|"
  if [ -f "$report" ]; then
    # Campaign rows only (a date in the second column), not the sums below.
    grep -E '^\| [a-z_]+ \| [0-9]{4}-[0-9]{2}-[0-9]{2} \|' "$report" | while read -r row; do
      name=$(echo "$row" | awk -F'|' '{gsub(/ /, "", $2); print $2}')
      # A harness of this run without a new row (its campaign did not finish) keeps its old one.
      [ -f "build-fuzz/$name/row" ] && case " ${harnesses[*]} " in *" $name "*) continue ;; esac
      echo "$row"
    done
  fi
  for h in "${harnesses[@]}"; do [ ! -f "build-fuzz/$h/row" ] || cat "build-fuzz/$h/row"; done
  echo
  echo "## All campaigns of each harness's current source"
  echo
  echo "Summed from \`fuzz/campaigns.csv\` (one line per campaign) over the campaigns whose harness"
  echo "source is the one in this commit: the same checks, each campaign starting from the inputs the"
  echo "ones before it saved; the library may have changed between them."
  echo
  echo "| harness | source SHA-256 | campaigns | process-seconds | executions | findings |"
  echo "|---|---|---|---|---|---|"
  [ -f "$campaigns" ] || echo "| (no campaign recorded yet) | | | | | |"
  for f in fuzz/fuzz_*.cpp; do
    h=${f#fuzz/fuzz_}
    h=${h%.cpp}
    sha=$(harness_sha "$h")
    [ -f "$campaigns" ] || break
    awk -F, -v h="$h" -v sha="$sha" '$1 == h && $2 == sha {
        n++; e += $5; f += $7; s = $4; sub(/^about_/, "", s); t += s * ($8 == "" ? 1 : $8) }
      END { if (n) printf "| %s | %s | %d | %d | %d | %d |\n", h, sha, n, t, e, f }' "$campaigns"
  done
  echo
  echo "## Findings saved as regression inputs"
  echo
  found=0
  for f in fuzz/corpus/*/crash-* fuzz/corpus/*/timeout-* fuzz/corpus/*/oom-*; do
    [ -e "$f" ] || continue
    found=1
    echo "- \`$f\`"
  done
  [ "$found" = 1 ] || echo "none"
} > "$part"
chmod 644 "$part"
mv "$part" "$report"
