#!/usr/bin/env bash
# The sanitizer suite (part of scripts/test.sh): builds the `sanitize` preset into build/sanitize
# (clang -O1, ASan + UBSan, libFuzzer instrumentation; the tests of every core module and of the CLI,
# no editor, no benchmarks: CMakePresets.json) and runs its ctest: those tests under
# the sanitizers, then each loader's libFuzzer target (tests/fuzz) over its committed corpus and for
# VISEMELAB_FUZZ_SECONDS seconds (default 10) of mutations.
# Usage: scripts/sanitize.sh [ctest arguments, e.g. -L fuzz (fuzzers only) or -R Obj]
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
