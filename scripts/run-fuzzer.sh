#!/usr/bin/env bash
# Runs one libFuzzer target (tests/fuzz) the way the test suite does: first every committed input of
# its corpus once (seeds and the regression inputs of crashes found earlier), then mutations for a
# bounded time, with a copy of the corpus in WORKDIR so the repository is never modified.
# Usage: scripts/run-fuzzer.sh FUZZER CORPUS_DIR WORKDIR [SECONDS]
#   SECONDS defaults to $VISEMELAB_FUZZ_SECONDS or 10. A crash leaves its input in WORKDIR/artifacts;
#   add it to CORPUS_DIR (named regression-*) once fixed, so it is replayed by every later run.
set -euo pipefail
fuzzer=${1:?usage: run-fuzzer.sh FUZZER CORPUS_DIR WORKDIR [SECONDS]}
corpus=${2:?usage: run-fuzzer.sh FUZZER CORPUS_DIR WORKDIR [SECONDS]}
work=${3:?usage: run-fuzzer.sh FUZZER CORPUS_DIR WORKDIR [SECONDS]}
seconds=${4:-${VISEMELAB_FUZZ_SECONDS:-10}}

rm -rf "$work/corpus"
mkdir -p "$work/corpus" "$work/artifacts"
cp -r "$corpus"/. "$work/corpus/"
# Readers refuse or bound what inputs declare; 1 GB or one 5 s input is a bug, as is any leak. JSON
# and glTF targets take inputs up to 2 MB, so quadratic parsing and amplification (one accessor used
# by hundreds of primitives) are reachable; the others keep 64 KB.
case "$(basename "$fuzzer")" in
  fuzz_project|fuzz_frequencies|fuzz_weights|fuzz_phoneme_map|fuzz_speech_track|fuzz_viseme_file|fuzz_gltf_*)
    max_len=2097152 ;;
  *) max_len=65536 ;;
esac
options=(-rss_limit_mb=1024 -malloc_limit_mb=1024 -timeout=5 -max_len=$max_len -print_final_stats=1
         -artifact_prefix="$work/artifacts/")
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}

echo "replaying $(find "$corpus" -type f | wc -l) committed inputs of $corpus"
find "$corpus" -type f -print0 | xargs -0 -r "$fuzzer" "${options[@]}" 2>&1 | tail -n 5
echo "fuzzing $(basename "$fuzzer") for ${seconds}s"
"$fuzzer" "${options[@]}" -max_total_time="$seconds" "$work/corpus" 2>&1 | tail -n 30
exit "${PIPESTATUS[0]}"
