#!/usr/bin/env bash
# The main job on the bundled sample: the editor when a display exists, the headless pipeline otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
bin=build/release/app
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && [ -x build/release/ui/visemelab-editor ]; then
  exec build/release/ui/visemelab-editor --project assets/sample/sample.vlproj
fi
out=out/sample-reduction
echo "No display: running the headless pipeline on the bundled sample (15 visemes -> 10)."
"$bin/visemelab" reduce --visemes assets/sample \
  --freq-file assets/phonemes/en-us_frequencies.csv --map assets/phonemes/map_sample_face.csv \
  --weights area --target 10 --out "$out"
echo "Results: $(pwd)/$out (merged OBJ + VRML meshes, mapping.json, report.json)"
