#!/usr/bin/env bash
# Times `visemelab say "TEXT" --avatar A.glb --out track.json --wav W --glb ANIM.glb` on a
# 10-word sentence against its floor measured in the same run (issue 29's goal: <= 2x the floor).
# The floor is what any tool doing the job must spend: espeak-ng's own synthesis of the sentence to a
# WAV (`espeak-ng -w`), plus reading the avatar (`visemelab avatar inspect`, process start included)
# plus writing a file of the avatar's size (`cp`). Process CPU time (user + sys), min/median/max of
# interleaved runs; `say -m 6` (the avatar also reduced in memory) is shown beside it. Avatars: the Ready Player Me-like fixture (532 vertices) and the 30k-vertex one.
# Usage: scripts/bench-say-avatar.sh [runs] [path/to/visemelab]
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-11}
cli=${2:-build/release/app/visemelab}
fixtures=build/release/tests/gltf/write_avatar_fixtures
[ -x "$cli" ] && [ -x "$fixtures" ] || { echo "no $cli or $fixtures: build first (scripts/build.sh)" >&2; exit 2; }
command -v espeak-ng >/dev/null || { echo "espeak-ng is not installed (scripts/install-deps.sh)" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$fixtures" "$out" --bench >/dev/null
python3 - "$runs" "$cli" "$out" <<'PY'
import os, statistics, subprocess, sys
runs, cli, out = int(sys.argv[1]), sys.argv[2], sys.argv[3]
sentence = "The quick brown fox jumps over the lazy sleeping dog"  # 10 words

sys.path.insert(0, "scripts")
from process_cpu import cpu_seconds

def line(values):
    return "min %.1f ms, median %.1f ms, max %.1f ms" % tuple(1000 * v for v in
                                                        (min(values), statistics.median(values), max(values)))

for stem in ("rpm_plain", "rpm_30k"):
    avatar = os.path.join(out, stem + ".glb")
    say = [cli, "say", sentence, "--avatar", avatar, "--out", out + "/track.json",
           "--wav", out + "/say.wav", "--glb", out + "/anim.glb", "--quiet"]
    reduced = say[:5] + ["-m", "6"] + say[5:]  # also reduces the avatar in memory (informative)
    espeak = ["espeak-ng", "-v", "en-us", "-w", out + "/espeak.wav", sentence]
    inspect = [cli, "avatar", "inspect", avatar]
    copy = ["cp", avatar, out + "/copy.glb"]
    t = {"say": [], "say -m 6": [], "espeak": [], "inspect": [], "cp": []}
    for _ in range(runs):  # interleaved, so every part sees the same machine load
        t["say"].append(cpu_seconds(say))
        t["say -m 6"].append(cpu_seconds(reduced))
        t["espeak"].append(cpu_seconds(espeak))
        t["inspect"].append(cpu_seconds(inspect))
        t["cp"].append(cpu_seconds(copy))
    floor = [e + i + c for e, i, c in zip(t["espeak"], t["inspect"], t["cp"])]
    ratios = sorted(s / f for s, f in zip(t["say"], floor))
    print("%s (%d bytes), %d runs, process CPU:" % (stem, os.path.getsize(avatar), runs))
    for name in ("say", "say -m 6", "espeak", "inspect", "cp"):
        print("  %-9s %s" % (name, line(t[name])))
    print("  floor     %s" % line(floor))
    print("  say / floor per run: min %.2f, median %.2f, max %.2f; goal <= 2: %s"
          % (ratios[0], statistics.median(ratios), ratios[-1],
             "met" if statistics.median(ratios) <= 2 else "NOT met"))
PY
