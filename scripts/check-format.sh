#!/usr/bin/env bash
# Fails when a tracked C++ file differs from the repository's .clang-format style (CMake files are
# never formatted). Exits 77 (skipped) when clang-format is not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "clang-format not installed: skipped"; exit 77; }
git ls-files '*.cpp' '*.h' | xargs clang-format --dry-run -Werror
echo "all C++ sources match .clang-format"
