#!/usr/bin/env bash
# The sanitizer suite (part of scripts/test.sh): builds the `sanitize` preset into build/sanitize
# (clang, ASan + UBSan, libFuzzer instrumentation; no editor, no benchmarks) and runs every test but
# the editor's under the sanitizers, then each loader's libFuzzer target (tests/fuzz) for
# VISEMELAB_FUZZ_SECONDS seconds (default 10) after replaying its committed corpus.
# Usage: scripts/sanitize.sh [ctest arguments, e.g. -L fuzz or -R Obj]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
start=$SECONDS
cmake --preset sanitize >/dev/null
cmake --build --preset sanitize
echo "sanitize build: $((SECONDS - start)) s"
start=$SECONDS
ctest --preset sanitize -j2 "$@"
echo "sanitize tests and fuzzing: $((SECONDS - start)) s"
