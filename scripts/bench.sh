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
./scripts/bench-say.sh
