#!/usr/bin/env bash
# The project's full test command (CI runs it through .ci/run on a clean clone: 2 cores, no GPU).
#   1. Release build (installs missing Debian packages first) and every test of it: unit, CLI,
#      editor click tests under Xvfb, glTF validators, format check.
#   2. The sanitizer suite (scripts/sanitize.sh): the file-reading modules' and the CLI's tests built
#      with clang ASan + UBSan and run under them, then every loader's libFuzzer target over its
#      corpus for a bounded time (VISEMELAB_FUZZ_SECONDS: 5 s each here, to keep the whole run within
#      CI's 30 minutes on 2 cores; scripts/sanitize.sh alone defaults to 10 s).
# Times measured on 2 cores: docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
./scripts/build.sh
ctest --preset release -j2
echo "release build and tests: $((SECONDS - start)) s"
VISEMELAB_FUZZ_SECONDS=${VISEMELAB_FUZZ_SECONDS:-5} ./scripts/sanitize.sh
echo "scripts/test.sh: all passed in $((SECONDS - start)) s"
