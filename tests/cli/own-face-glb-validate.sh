#!/usr/bin/env bash
# Own-face visemes through the Khronos glTF validator: `face build` on the MediaPipe canonical face,
# `refine --project --save` (the refined mesh stored in the project), `export --format glb`, then
# scripts/gltf-validate.sh on the glb. Exits 77 (ctest: skipped) when the shared data is absent or the
# validator cannot be installed.
# Usage: own-face-glb-validate.sh VISEMELAB_CLI SHARED_DATA_DIR WORK_DIR VALIDATOR_TOOLDIR
set -euo pipefail
cli=${1:?usage: own-face-glb-validate.sh CLI DATA WORK TOOLDIR}
data=${2:?}
work=${3:?}
tooldir=${4:?}
mesh="$data/mediapipe-canonical-face/canonical_face_model.obj"
if [ ! -f "$mesh" ]; then
  echo "SKIPPED: shared data missing: $mesh (set VISEMELAB_SHARED_DATA_DIR)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
"$cli" face build "$mesh" --out "$work/face.vlproj"
"$cli" refine --project "$work/face.vlproj" --save --criterion contour --max-depth 5
"$cli" export "$work/face.vlproj" --format glb --out "$work/face.glb"
"$cli" export "$work/face.vlproj" --format glb --unreduced --out "$work/face-all.glb"
exec "$(dirname "$0")/../../scripts/gltf-validate.sh" "$tooldir" "$work/face.glb" "$work/face-all.glb"
