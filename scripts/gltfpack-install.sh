#!/usr/bin/env bash
# Installs gltfpack (meshoptimizer's glTF packer, npm package `gltfpack`) once into TOOLDIR, for
# `visemelab avatar reduce --gltfpack` in the tests: VISEMELAB_GLTFPACK=TOOLDIR/node_modules/.bin/gltfpack.
# Exits 0 when it is there, 77 (ctest: skipped) when npm is missing or the registry cannot be reached.
# Usage: scripts/gltfpack-install.sh TOOLDIR
set -euo pipefail
tooldir=${1:?usage: gltfpack-install.sh TOOLDIR}
version=1.3.0
if [ -x "$tooldir/node_modules/.bin/gltfpack" ]; then
  echo "$tooldir/node_modules/.bin/gltfpack"
  exit 0
fi
for tool in node npm; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIPPED: $tool not found; install nodejs and npm (scripts/install-deps.sh) to get gltfpack"
    exit 77
  fi
done
mkdir -p "$tooldir"
echo "installing gltfpack@$version into $tooldir"
if ! npm install --prefix "$tooldir" --no-audit --no-fund --loglevel=error "gltfpack@$version" >"$tooldir/npm.log" 2>&1; then
  tail -n 5 "$tooldir/npm.log"
  echo "SKIPPED: could not install gltfpack from the npm registry (see $tooldir/npm.log)"
  exit 77
fi
echo "$tooldir/node_modules/.bin/gltfpack"
