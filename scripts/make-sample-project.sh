#!/usr/bin/env bash
# Rewrites assets/sample/sample.vlproj, the bundled sample project, from the sample meshes in
# assets/sample (scripts/generate-sample.sh makes them): run it after regenerating them.
# It runs the default rest model (auto: the rest free, sil rests), as every new project does.
# Usage: scripts/make-sample-project.sh [path/to/visemelab]
set -euo pipefail
cd "$(dirname "$0")/.."
cli=${1:-build/release/app/visemelab}
"$cli" project new --out assets/sample/sample.vlproj --visemes assets/sample \
  --phonemes assets/phonemes/en-us_frequencies.csv --map assets/phonemes/map_sample_face.csv \
  --weights area --target 10 --face bundled --reduce \
  --order sil,PP,FF,TH,DD,kk,CH,SS,nn,RR,aa,E,ih,oh,ou
"$cli" project check assets/sample/sample.vlproj
