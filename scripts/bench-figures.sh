#!/usr/bin/env bash
# The headline figures of docs/performance.md in one run, between two readings of the machine's
# speed (scripts/machine-speed.sh), for re-measuring them on an idle machine (issue 33 point 4):
#   - BM_Reduce/16/10 and /20/10 (bench_reduce, 5 repetitions: min / median / max wall);
#   - `visemelab refine --criterion contour ...`: the timing the CLI reports, 11 runs;
#   - `reduce` of 1,000,000 vertices x 16 against its physical floor (scripts/bench-large-mesh.sh);
#   - `say` and `say --stdin` against espeak-ng (scripts/bench-say.sh);
#   - `visemelab --help` against /bin/true (scripts/bench-startup.sh).
# Usage: scripts/bench-figures.sh [runs for the process benchmarks, default 7]
# Needs a release build (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-7}
cli=build/release/app/visemelab
[ -x "$cli" ] || { echo "no $cli: build first (scripts/build.sh)" >&2; exit 2; }
./scripts/machine-speed.sh
trap './scripts/machine-speed.sh' EXIT

echo "== BM_Reduce (bench_reduce, 5 repetitions, wall)"
build/release/tests/bench/bench_reduce --benchmark_filter='^BM_Reduce/(16/10|20/10)/' \
  --benchmark_repetitions=5 --benchmark_format=json 2>/dev/null | python3 -c '
import json, statistics, sys
runs = {}
for b in json.load(sys.stdin)["benchmarks"]:
    if b.get("run_type") == "iteration":
        runs.setdefault(b["run_name"], []).append(b["real_time"] * {"ms": 1, "us": 1e-3, "ns": 1e-6}[b["time_unit"]])
for name, ms in runs.items():
    print("%-18s min %.1f ms, median %.1f ms, max %.1f ms (%d runs)" % (name, min(ms), statistics.median(ms), max(ms), len(ms)))
'

echo "== refine --criterion contour (the timing the CLI reports)"
out=$(mktemp -d)
trap 'rm -rf "$out"; ./scripts/machine-speed.sh' EXIT
for _ in $(seq 11); do
  "$cli" refine --criterion contour --param jaw_open=1 --param lip_pucker=0.5 --out "$out/refined.obj" |
    grep -o '[0-9.]* ms' | head -1
done | python3 -c '
import statistics, sys
ms = [float(line.split()[0]) for line in sys.stdin]
print("refine reported: min %.1f ms, median %.1f ms, max %.1f ms (%d runs)" % (min(ms), statistics.median(ms), max(ms), len(ms)))
'

echo "== reduce 1,000,000 x 16 against its floor"
./scripts/bench-large-mesh.sh "$runs"
echo "== say against espeak-ng"
./scripts/bench-say.sh "$runs"
echo "== --help against /bin/true"
./scripts/bench-startup.sh 50
