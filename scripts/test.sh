#!/usr/bin/env bash
# Installs missing Debian packages (idempotent), builds everything and runs all tests.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh
ctest --preset release -j2
