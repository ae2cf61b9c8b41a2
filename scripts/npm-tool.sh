#!/usr/bin/env bash
# Installs an npm package once into TOOLDIR (outside the repository, e.g. the build folder).
# Exits 77 (ctest: skipped) when node/npm are missing or the npm registry cannot be reached.
# Usage: scripts/npm-tool.sh TOOLDIR PACKAGE@VERSION
set -euo pipefail
tooldir=${1:?usage: npm-tool.sh TOOLDIR PACKAGE@VERSION}
package=${2:?usage: npm-tool.sh TOOLDIR PACKAGE@VERSION}
name=${package%@*}
for tool in node npm; do
  if ! command -v "$tool" >/dev/null 2>&1; then
    echo "SKIPPED: $tool not found; install nodejs and npm (scripts/install-deps.sh)"
    exit 77
  fi
done
if [ ! -f "$tooldir/node_modules/$name/package.json" ]; then
  mkdir -p "$tooldir"
  echo "installing $package into $tooldir"
  if ! npm install --prefix "$tooldir" --no-audit --no-fund --loglevel=error "$package" >"$tooldir/npm.log" 2>&1; then
    tail -n 5 "$tooldir/npm.log"
    echo "SKIPPED: could not install $package from the npm registry (see $tooldir/npm.log)"
    exit 77
  fi
fi
