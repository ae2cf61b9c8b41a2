#!/usr/bin/env bash
# Installs missing Debian packages (idempotent) and builds VisemeLab (Release) into build/release.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
