#!/usr/bin/env bash
# Throughput of `visemelab batch` against separate `visemelab say` calls (issue 34): N ten-word
# sentences (default 1,000) on the bundled sample project, each a track JSON; the separate calls run
# two at a time (xargs -P 2), both on 2 cores (taskset when the machine has more). Wall time of
# repeated runs (min / median / max), sentences per second and the ratio of the medians. Goal:
# batch >= 1.8x the separate calls' throughput. The speech cache is warm for both (one say first).
# Usage: scripts/bench-batch.sh [runs] [sentences] [path/to/visemelab]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
sentences=${2:-1000}
cli=${3:-build/release/app/visemelab}
[ -x "$cli" ] || { echo "no $cli: build first (scripts/build.sh)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
pin=()
if command -v taskset >/dev/null && [ "$(nproc)" -gt 2 ]; then pin=(taskset -c 0,1); fi
python3 - "$runs" "$sentences" "$cli" "$out" "${pin[@]}" <<'PY'
import json, os, shutil, statistics, subprocess, sys, time
runs, n, cli, out = int(sys.argv[1]), int(sys.argv[2]), os.path.abspath(sys.argv[3]), sys.argv[4]
pin = sys.argv[5:]
project = os.path.abspath("assets/sample/sample.vlproj")
words = ["quick", "brown", "foxes", "jump", "over", "lazy", "dogs", "while", "seven", "sailors", "sing",
         "softly", "about", "shells", "and", "rain"]
texts = ["%s %s" % (("Number %d" % i), " ".join(words[(i * 7 + k * 3) % 16] for k in range(8))) for i in range(n)]
env = dict(os.environ, VISEMELAB_CACHE_DIR=os.path.join(out, "cache"))
with open(os.path.join(out, "jobs.jsonl"), "w") as f:
    for i, text in enumerate(texts):
        f.write(json.dumps({"id": "s%d" % i, "command": "say", "text": text, "project": project}) + "\n")
# One argument list per call for xargs -0: say TEXT --project P --out FILE --quiet.
with open(os.path.join(out, "calls"), "wb") as f:
    for i, text in enumerate(texts):
        args = ["say", text, "--project", project, "--out", os.path.join(out, "single", "s%d.json" % i), "--quiet"]
        f.write(("\0".join(args) + "\n").encode())
subprocess.run([cli, "say", texts[0], "--project", project, "--out", os.path.join(out, "warm.json"), "--quiet"],
               env=env, check=True, stderr=subprocess.DEVNULL)

def timed(command):
    start = time.monotonic()
    subprocess.run(pin + command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start

batch_cmd = [cli, "batch", os.path.join(out, "jobs.jsonl"), "--out", os.path.join(out, "batch"), "--no-resume"]
# Each line of `calls` is one say call; a small driver runs them two at a time.
driver = ["sh", "-c", "tr '\\n' '\\0' < %s | xargs -0 -n 7 -P 2 %s" % (os.path.join(out, "calls"), cli)]
times = {"batch": [], "separate say": []}
for _ in range(runs):  # interleaved, so both see the same machine load
    for d in ("batch", "single"):
        shutil.rmtree(os.path.join(out, d), ignore_errors=True)
    os.makedirs(os.path.join(out, "single"))
    times["batch"].append(timed(batch_cmd))
    times["separate say"].append(timed(driver))
    made = len(os.listdir(os.path.join(out, "single")))
    batched = len([f for f in os.listdir(os.path.join(out, "batch")) if f.endswith(".json")])
    assert made == batched == n, "tracks written: %d by the separate calls, %d by batch, of %d" % (made, batched, n)
for name, t in times.items():
    print("%-12s %d sentences: wall time min %.2f s, median %.2f s, max %.2f s (%d runs); %.1f sentences/s"
          % (name, n, min(t), statistics.median(t), max(t), runs, n / statistics.median(t)))
ratio = statistics.median(times["separate say"]) / statistics.median(times["batch"])
print("batch throughput / separate say throughput (medians): %.2fx; goal >= 1.8x: %s"
      % (ratio, "met" if ratio >= 1.8 else "NOT met"))
PY
