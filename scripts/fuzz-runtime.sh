#!/usr/bin/env bash
# Builds the runtime package loader's libFuzzer target with clang (ASan + UBSan) and runs it for a
# bounded time on a seed corpus. Exits 77 (ctest: skipped) when clang's libFuzzer is unavailable;
# GCC-only machines still run the deterministic mutation test (test_runtime RuntimeMutationFuzz).
# Usage: scripts/fuzz-runtime.sh WORKDIR [SECONDS=30] [SEED_WRITER]
set -euo pipefail
work=${1:?usage: fuzz-runtime.sh WORKDIR [SECONDS] [SEED_WRITER]}
seconds=${2:-30}
seed_writer=${3:-}
root=$(cd "$(dirname "$0")/.." && pwd)
cxx=${FUZZ_CXX:-clang++}

mkdir -p "$work/corpus"
if ! command -v "$cxx" >/dev/null 2>&1; then
  echo "SKIPPED: $cxx not found; libFuzzer needs clang (the mutation test in test_runtime still ran)"
  exit 77
fi
probe="$work/probe.cpp"
printf '#include <cstdint>\n#include <cstddef>\nextern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }\n' >"$probe"
if ! "$cxx" -fsanitize=fuzzer "$probe" -o "$work/probe" >/dev/null 2>&1; then
  echo "SKIPPED: $cxx cannot link -fsanitize=fuzzer (install libclang-rt-dev)"
  exit 77
fi

if [ -n "$seed_writer" ]; then "$seed_writer" "$work/corpus"; fi
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(ccache); fi
"${launcher[@]}" "$cxx" -std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
  -I"$root" -I"$root/tests/runtime" \
  "$root/core/runtime/Crc32.cpp" "$root/core/runtime/Package.cpp" "$root/core/runtime/Animation.cpp" \
  "$root/tests/runtime/FuzzTarget.cpp" "$root/tests/runtime/fuzz_runtime_package.cpp" \
  -o "$work/fuzz_runtime_package"
echo "fuzzing the runtime package loader for ${seconds}s (corpus: $work/corpus)"
"$work/fuzz_runtime_package" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
  "$work/corpus" 2>&1 | tail -n 25
exit "${PIPESTATUS[0]}"
