#!/usr/bin/env bash
# Builds and runs the benchmarks whose figures docs/performance.md records.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
for b in build/release/tests/bench/bench_*; do
  [ -x "$b" ] && "$b" "$@"
done
