#!/usr/bin/env bash
# Times `visemelab say` on a 100-word paragraph (the first 100 words of
# assets/speech/gettysburg.txt) with the bundled sample project: process CPU time (user + sys,
# the audio is written, never played), min/median/max of repeated runs, against a baseline
# measured in the same run: `visemelab freq` on the same text (process start, espeak-ng start,
# transcription). Goal: say <= 0.3 s.
# Usage: scripts/bench-say.sh [runs] [path/to/visemelab]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-15}
cli=${2:-build/release/app/visemelab}
[ -x "$cli" ] || { echo "no $cli: build first (scripts/build.sh)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
tr -s ' \n' '  ' <assets/speech/gettysburg.txt | cut -d' ' -f1-100 >"$out/paragraph.txt"
python3 - "$runs" "$cli" "$out" <<'PY'
import os, statistics, subprocess, sys
runs, cli, out = int(sys.argv[1]), sys.argv[2], sys.argv[3]
paragraph = open(os.path.join(out, "paragraph.txt")).read().strip()

sys.path.insert(0, "scripts")
from process_cpu import cpu_seconds

say = [cli, "say", paragraph, "--project", "assets/sample/sample.vlproj", "--out", out + "/track.json",
       "--wav", out + "/audio.wav", "--glb", out + "/anim.glb", "--quiet"]
freq = [cli, "freq", out + "/paragraph.txt", "--quiet"]
results = {"say": [], "freq": []}
for _ in range(runs):  # interleaved, so both see the same machine load
    results["say"].append(cpu_seconds(say))
    results["freq"].append(cpu_seconds(freq))
words = len(paragraph.split())
for name, times in results.items():
    print("%-4s %d words: process CPU time min %.3f s, median %.3f s, max %.3f s (%d runs)"
          % (name, words, min(times), statistics.median(times), max(times), runs))
ratio = statistics.median(results["say"]) / statistics.median(results["freq"])
print("say / freq (median): %.2f; goal say <= 0.3 s: %s"
      % (ratio, "met" if statistics.median(results["say"]) <= 0.3 else "NOT met"))
PY
