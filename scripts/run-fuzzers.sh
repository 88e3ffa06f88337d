#!/usr/bin/env bash
# Builds the libFuzzer harnesses (preset "fuzz": clang 16, ASan + UBSan)
# and runs each one, from the seed corpus of real files in fuzz/seeds/.
# Usage: scripts/run-fuzzers.sh [RUNS [SECONDS]]   (default 1000000 runs, at most 600 s each)
# Findings (crashes, hangs, leaks) go to build/fuzz/findings/HARNESS/;
# the grown corpora stay in build/fuzz/corpus/HARNESS/.
set -euo pipefail
cd "$(dirname "$0")/.."

runs="${1:-1000000}"
seconds="${2:-600}"
bash scripts/install-deps.sh fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz

status=0
for harness in manifest exr selection camera_path region pose_table store numeric tile_plan tile_outcome; do
  corpus="build/fuzz/corpus/$harness"
  findings="build/fuzz/findings/$harness"
  mkdir -p "$corpus" "$findings"
  cp -n fuzz/seeds/"$harness"/* "$corpus"/
  echo "== $harness: up to $runs runs or $seconds s"
  if ! "build/fuzz/fuzz/${harness}_fuzzer" "$corpus" -runs="$runs" -max_total_time="$seconds" -timeout=10 \
      -rss_limit_mb=4096 -max_len=65536 -print_final_stats=1 -artifact_prefix="$findings/" \
      2> "build/fuzz/$harness.log"; then
    echo "triwalk: $harness found a problem: see build/fuzz/$harness.log and $findings/" >&2
    status=1
  fi
  grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+.*DONE" "build/fuzz/$harness.log" || true
done
exit "$status"
