#!/usr/bin/env bash
# Regenerates the user guide's editor pictures (docs/images/editor-*.png) from the current build:
# each picture is the editor's --screenshot mode on the bundled sample (the avatar picture: a generated
# avatar) under a private Xvfb.
# Usage: scripts/guide-pictures.sh [build/release]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
editor="$build/ui/visemelab-editor"
[ -x "$editor" ] || { echo "guide-pictures: build the editor first ($editor not found)" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "guide-pictures: xvfb-run is not installed (apt-get install xvfb xauth)" >&2; exit 2; }

shot() { # shot NAME ARGS... : one picture at 1280x800
  local name="$1"
  shift
  xvfb-run -a -s '-screen 0 1600x1000x24' "$editor" --size 1280 800 --sample "$@" \
    --screenshot "docs/images/editor-$name.png" >/dev/null
  echo "docs/images/editor-$name.png"
}

shot visemes --frames 8 --screenshot-bits 6 --panel Visemes --viseme ou --no-wireframe
shot sculpt --frames 20 --screenshot-bits 6 --panel Visemes --viseme ou --sculpt grab --drag 900 520 915 500 --no-wireframe
shot frequencies --frames 8 --screenshot-bits 6 --panel Frequencies --no-wireframe
shot phoneme-map --frames 8 --screenshot-bits 6 --panel Frequencies --map-start mpeg4 --no-wireframe
shot weights --screenshot-bits 6 --panel Weights --weights uniform --brush subtract --drag 760 380 1010 410 --frames 20 --no-wireframe
shot deformation --frames 8 --panel Deformation --preset oh --field zygomatic_l --no-wireframe --screenshot-bits 5
# Use my mesh: the landmarks as dots on the mesh (the MediaPipe canonical face from the shared data
# when it is there, else the sample's neutral, whose landmarks the finder only partly sees).
ownface=../shared/data/mediapipe-canonical-face/canonical_face_model.obj
[ -f "$ownface" ] || ownface=assets/sample/neutral.obj
shot own-face --frames 10 --panel Deformation --own-face "$ownface" --no-wireframe --screenshot-bits 6
shot refinement --frames 8 --panel Refinement --refine contour --preset aa --screenshot-bits 4
shot reduction --frames 8 --screenshot-bits 6 --panel Reduction --viseme E --no-wireframe
shot reduction-overlay --frames 8 --screenshot-bits 6 --panel Reduction --viseme E --merged overlay --no-wireframe
shot playback --frames 8 --screenshot-bits 6 --panel Reduction --play 1.3 --sequence 'HH EH L OW W ER L D' --no-wireframe
shot export --frames 8 --screenshot-bits 6 --panel Export --no-wireframe
# The View menu, opened by a scripted press on its title (x 100, y 10 in the menu bar).
shot view-menu --frames 10 --screenshot-bits 6 --panel Visemes --viseme aa --no-wireframe --drag 100 10 100 10
shot view-right --frames 8 --screenshot-bits 6 --panel Visemes --viseme aa --view right --orthographic

# docs/avatars.md: the generated Ready Player Me-like avatar (tests/gltf/AvatarFixtures.h) in the
# Reduction panel's before/after views, its body greyed.
fixtures=$(mktemp -d)
trap 'rm -rf "$fixtures"' EXIT
"$build/tests/gltf/write_avatar_fixtures" "$fixtures" >/dev/null
xvfb-run -a -s '-screen 0 1600x1000x24' "$editor" --size 1280 800 --avatar "$fixtures/rpm_plain.glb" \
  --frames 10 --screenshot-bits 6 --panel Reduction --viseme viseme_aa --no-wireframe \
  --screenshot docs/images/editor-avatar.png >/dev/null
echo docs/images/editor-avatar.png
# The same avatar in its materials (the skin texture, the eyes' and the body's colours), the
# Materials | Error colours switch in the view's corner.
xvfb-run -a -s '-screen 0 1600x1000x24' "$editor" --size 1280 800 --avatar "$fixtures/rpm_plain.glb" \
  --frames 10 --screenshot-bits 6 --panel Visemes --viseme viseme_aa --surface materials \
  --screenshot docs/images/editor-materials.png >/dev/null
echo docs/images/editor-materials.png
