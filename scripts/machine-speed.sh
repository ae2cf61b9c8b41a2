#!/usr/bin/env bash
# The machine's speed state, for the record beside benchmark figures (issue 33 point 4): date, load
# average, cores, CPU model, and the CPU time of a fixed calibration loop (tests/bench/floor/
# calibrate.c, built here with cc -O2) as min / median / max of 5 runs. A figure measured while the
# loop took 1.3x its idle time is not comparable with one measured idle: compare ratios measured in
# one run, or figures divided by the loop's median.
# Usage: scripts/machine-speed.sh [runs=5]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc -O2 -o "$work/calibrate" tests/bench/floor/calibrate.c
times=()
for _ in $(seq "$runs"); do times+=("$("$work/calibrate" | cut -d' ' -f1)"); done
sorted=$(printf '%s\n' "${times[@]}" | sort -n)
median=$(printf '%s\n' "$sorted" | sed -n "$(((runs + 1) / 2))p")
echo "machine: $(date -u '+%Y-%m-%d %H:%M UTC'), load average $(cut -d' ' -f1-3 /proc/loadavg)," \
  "$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "calibration loop (2^28 xorshift steps): min $(printf '%s\n' "$sorted" | head -1) ms," \
  "median $median ms, max $(printf '%s\n' "$sorted" | tail -1) ms ($runs runs)"
