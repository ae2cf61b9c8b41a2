#!/usr/bin/env bash
# The bundled visemes against reference mouth shapes (docs/viseme-review.md): measures the mouth of
# every viseme of the bundled sample (assets/sample, written by scripts/generate-sample.sh) against the
# neutral face with `visemelab face mouth`, prints the Markdown table of the measures, and renders the
# front close-up of the 15 visemes' mouths (docs/images/viseme-review-mouths.png) from a finer grid of
# the same face.
# Usage: scripts/viseme-review.sh [--no-images]
set -euo pipefail
cd "$(dirname "$0")/.."
# VISEMELAB_CLI=path/to/visemelab skips the build and uses that binary.
cli=${VISEMELAB_CLI:-build/release/app/visemelab}
if [ -z "${VISEMELAB_CLI:-}" ]; then
  cmake --preset release >/dev/null
  cmake --build --preset release --target visemelab
fi

order=(sil PP FF TH DD kk CH SS nn RR aa E ih oh ou)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The measures, on the meshes the project bundles (1,532 skin vertices; the lip landmarks are vertices).
meshes=()
for v in "${order[@]}"; do meshes+=("assets/sample/$v.obj"); done
"$cli" face mouth --neutral assets/sample/neutral.obj "${meshes[@]}" --json "$tmp/mouth.json" | grep '^|'

if [ "${1:-}" = "--no-images" ]; then exit 0; fi
# Pictures: the same parameter vectors on a finer grid (110 cells across, smoother lips), seen from the
# front. The close-up frames a sphere round the neutral mouth's centre, the same for every viseme.
"$cli" visemes --face bundled --resolution 110 --density mouth --out "$tmp/fine" >/dev/null
focus=$(python3 - "$tmp/mouth.json" <<'EOF'
import json, sys
m = json.load(open(sys.argv[1]))["neutral"]["landmarks"]
r, l = m["mouth_corner_right"], m["mouth_corner_left"]
u, d = m["upper_lip_mid"], m["lower_lip_mid"]
centre = [(r[k] + l[k]) / 2 for k in range(3)]
centre[1] = (u[1] + d[1]) / 2 - 0.6  # a little below the lips: the open jaw drops
width = ((l[0] - r[0]) ** 2 + (l[1] - r[1]) ** 2 + (l[2] - r[2]) ** 2) ** 0.5
print(",".join(f"{x:.3f}" for x in centre + [0.8 * width]))
EOF
)
fine=()
for v in "${order[@]}"; do fine+=("$tmp/fine/$v.obj"); done
mkdir -p docs/images
"$cli" render "${fine[@]}" --face-colours --focus "$focus" --size 200x160 --columns 5 \
  --out docs/images/viseme-review-mouths.png >&2 # stdout keeps only the table
