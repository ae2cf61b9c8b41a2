#!/usr/bin/env bash
# Regenerates the bundled sample viseme set (assets/sample: neutral + the 15 Oculus visemes of the
# bundled deformable face, OBJ with (u,v), and visemes.json with the parameter vectors) and the
# preview pictures in docs/images. Builds only the visemelab CLI (Release) first.
# Usage: scripts/generate-sample.sh [--no-images]
set -euo pipefail
cd "$(dirname "$0")/.."
# VISEMELAB_CLI=path/to/visemelab skips the build and uses that binary.
cli=${VISEMELAB_CLI:-build/release/app/visemelab}
if [ -z "${VISEMELAB_CLI:-}" ]; then
  ./scripts/install-deps.sh
  cmake --preset release >/dev/null
  cmake --build --preset release --target visemelab
fi

# About 1,500 vertices / 2,900 triangles, grid lines gathered at the mouth and eyes.
mkdir -p assets/sample
"$cli" visemes --face bundled --resolution 38 --density mouth --out assets/sample

if [ "${1:-}" = "--no-images" ]; then exit 0; fi
mkdir -p docs/images
order=(sil PP FF TH DD kk CH SS nn RR aa E ih oh ou)
sheet=(assets/sample/neutral.obj)
for v in "${order[@]}"; do sheet+=("assets/sample/$v.obj"); done
"$cli" render "${sheet[@]}" --face-colours --size 150x180 --columns 8 --out docs/images/sample-visemes.png
"$cli" render assets/sample/neutral.obj --face-colours --wireframe --yaw 25 --pitch 5 --size 360x420 \
  --out docs/images/sample-neutral-wireframe.png

# The same fields on the second individual (retargeting), at a finer grid for the picture.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for face in bundled retarget; do
  "$cli" visemes --face "$face" --resolution 110 --density mouth --out "$tmp/$face" >/dev/null
done
"$cli" render "$tmp"/bundled/{neutral,aa,PP,ou,FF,E}.obj "$tmp"/retarget/{neutral,aa,PP,ou,FF,E}.obj \
  --face-colours --yaw 15 --pitch 3 --size 170x200 --columns 6 --out docs/images/retarget-visemes.png

# Bring your own face: the same parameters on faces nobody here made (docs/deformable-face.md),
# when the shared data is present (VISEMELAB_SHARED_DATA_DIR, default ../shared/data).
shared=${VISEMELAB_SHARED_DATA_DIR:-../shared/data}
if [ -f "$shared/mediapipe-canonical-face/canonical_face_model.obj" ]; then
  rows=("$tmp"/bundled/{neutral,aa,PP,ou,FF,E}.obj)
  for mesh in "$shared/mediapipe-canonical-face/canonical_face_model.obj" \
              "$shared/ict-facekit-mouth/generic_neutral_mesh.obj"; do
    [ -f "$mesh" ] || continue
    name=$(basename "$mesh" .obj)
    "$cli" face build "$mesh" --out "$tmp/$name.vlproj" >/dev/null
    "$cli" visemes --project "$tmp/$name.vlproj" --resolution 110 --density mouth --out "$tmp/$name" >/dev/null
    rows+=("$tmp/$name"/{neutral,aa,PP,ou,FF,E}.obj)
  done
  "$cli" render "${rows[@]}" --face-colours --yaw 15 --pitch 3 --size 170x200 --columns 6 \
    --out docs/images/own-face-visemes.png
else
  echo "generate-sample: no shared data at $shared: docs/images/own-face-visemes.png not regenerated" >&2
fi
