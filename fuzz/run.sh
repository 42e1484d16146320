#!/usr/bin/env bash
# Builds the fuzz harness with clang-14 (libFuzzer + ASan + UBSan) and runs it, time-boxed.
# Usage: bash fuzz/run.sh [seconds]   (default 120). Findings go to build-fuzz/{crash,timeout,oom}-*.
# Under ASan+UBSan an input costs ~15x its Release time; -timeout=60 flags only real hangs.
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-120}
bash scripts/install-deps.sh --fuzz
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DSYMMESH_FUZZ=ON -DSYMMESH_BUILD_TESTS=OFF -DSYMMESH_WERROR=OFF
cmake --build build-fuzz -j "$(nproc)" --target fuzz_templated_structure_json
mkdir -p build-fuzz/corpus
cp fuzz/corpus/json/* build-fuzz/corpus/ 2>/dev/null || true
./build-fuzz/fuzz/fuzz_templated_structure_json build-fuzz/corpus -max_total_time="$secs" \
  -max_len=4096 -timeout=60 -rss_limit_mb=4096 -artifact_prefix=build-fuzz/
