#!/usr/bin/env bash
# Builds and runs the benchmarks whose figures docs/performance.md records, then times the whole
# `visemelab reduce` process on the bundled sample (load 16 meshes, reduce 15 -> 10, write).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
for b in build/release/tests/bench/bench_*; do
  [ -x "$b" ] && "$b" "$@"
done
cli=build/release/app/visemelab
out=$(mktemp -d)
runs=20
start=$(date +%s%N)
for _ in $(seq $runs); do
  "$cli" reduce --visemes assets/sample --freq-file assets/phonemes/en-us_frequencies.csv \
    --map assets/phonemes/map_sample_face.csv --weights area --target 10 --out "$out" >/dev/null
done
end=$(date +%s%N)
echo "CLI reduce on the sample (16 meshes in, 10 merged out, OBJ+VRML+JSON written):" \
  "$(( (end - start) / runs / 1000000 )) ms per process (mean of $runs runs)"
python3 - "$out/report.json" 2>/dev/null <<'PY' || true
import json, sys
t = json.load(open(sys.argv[1]))["timing_ms"]
print("  last run: load %.1f ms, reduce %.1f ms, write %.1f ms" % (t["load"], t["reduce"], t["write"]))
PY
rm -rf "$out"

# Avatar reduce end to end on a generated 30,000-vertex avatar (15 visemes on 4 meshes): process
# wall and CPU time (user + sys), min/median/max of repeated runs, against `avatar inspect` (read
# and measure only) of the same file in the same run. Goal: <= 0.5 s process time.
fixtures=build/release/tests/gltf/write_avatar_fixtures
if [ -x "$fixtures" ]; then
  avatar=$(mktemp -d)
  "$fixtures" "$avatar" --bench >/dev/null
  python3 - "$cli" "$avatar" <<'PY'
import os, resource, statistics, subprocess, sys, time
cli, folder = sys.argv[1], sys.argv[2]
glb = os.path.join(folder, "rpm_30k.glb")
def measure(args, runs=11):
    wall, cpu = [], []
    for _ in range(runs):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        subprocess.run([cli] + args, check=True, stdout=subprocess.DEVNULL)
        wall.append(time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    return wall, cpu
def line(name, values):
    return "%s min %.3f s, median %.3f s, max %.3f s" % (name, min(values), statistics.median(values), max(values))
inspect = measure(["avatar", "inspect", glb])
reduce = measure(["avatar", "reduce", glb, "--target", "6", "--weights", "area", "--out", os.path.join(folder, "out.glb")])
print("avatar reduce, 30k-vertex avatar (15 visemes on 4 meshes, m = 6, area weights), %d runs:" % len(reduce[0]))
print("  process wall:", line("", reduce[0]))
print("  process CPU: ", line("", reduce[1]), "(goal <= 0.5 s)")
print("  baseline avatar inspect wall:", line("", inspect[0]))
print("  reduce / inspect (median wall): %.2f" % (statistics.median(reduce[0]) / statistics.median(inspect[0])))
PY
  rm -rf "$avatar"
fi

./scripts/bench-say.sh
