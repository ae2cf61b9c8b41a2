#!/usr/bin/env bash
# Regenerates the figures of docs/speech.md from the current build: the editor's Say timeline
# picture (docs/images/editor-say.png, the bundled sample paused mid-sentence under a private Xvfb)
# and the utterance error of the bundled sample at m = 6..12 on real text (the Gettysburg Address,
# the Harvard sentences of list 1), written between the "speech-figures" markers of docs/speech.md.
# Usage: scripts/speech-figures.sh [build/release]
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/release}"
editor="$build/ui/visemelab-editor"
cli="$build/app/visemelab"
for tool in "$editor" "$cli"; do
  [ -x "$tool" ] || { echo "speech-figures: build first ($tool not found)" >&2; exit 2; }
done
command -v xvfb-run >/dev/null || { echo "speech-figures: xvfb-run is not installed (apt-get install xvfb xauth)" >&2; exit 2; }

sentence="The birch canoe slid on the smooth planks." # Harvard list 1, sentence 1
xvfb-run -a -s '-screen 0 1600x1000x24' "$editor" --size 1280 800 --sample --panel Reduction \
  --say "$sentence" --say-at 1.02 --frames 8 --screenshot-bits 6 --no-wireframe \
  --screenshot docs/images/editor-say.png >/dev/null
echo "docs/images/editor-say.png"

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
project=assets/sample/sample.vlproj
for blend in cubic linear dominance; do
  "$cli" say --text-file assets/speech/gettysburg.txt --project "$project" --blend "$blend" \
    --out "$out/corpus-$blend.json" --quiet >/dev/null
done
"$cli" say "$sentence" --project "$project" --curve --out "$out/sentence.json" --quiet >/dev/null
"$cli" say --text-file assets/speech/harvard-list1.txt --project "$project" --out "$out/harvard.json" --quiet >/dev/null
python3 - "$out" "$sentence" <<'PY'
import json, re, subprocess, sys
out, sentence = sys.argv[1], sys.argv[2]
corpus = {b: json.load(open(f"{out}/corpus-{b}.json")) for b in ("cubic", "linear", "dominance")}
said = json.load(open(f"{out}/sentence.json"))
harvard = json.load(open(f"{out}/harvard.json"))
ms = range(6, 13)
def point(track, m):
    return next(p for p in track["errorCurve"] if p["m"] == m)
meta = corpus["cubic"]["metadata"]
phonemes = corpus["cubic"]["phonemes"]
pauses = sum(p["value"] == "sil" for p in phonemes)
espeak = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "libespeak-ng1"], capture_output=True, text=True).stdout
lines = [
    "<!-- speech-figures:begin (scripts/speech-figures.sh writes this block) -->",
    f"Gettysburg Address (`assets/speech/gettysburg.txt`, {meta['duration']:.1f} s, "
    f"{len(phonemes) - pauses} phonemes, {pauses} pauses):",
    "",
    "| m | reduction cost ρ_f | cubic: mean | max | of motion | linear: mean | dominance: mean | of motion |",
    "|---:|---:|---:|---:|---:|---:|---:|---:|",
]
for m in ms:
    c, l, d = (point(corpus[b], m) for b in ("cubic", "linear", "dominance"))
    lines.append(f"| {m} | {c['cost']:.4g} | {c['mean']:.4g} | {c['max']:.3g} | {100 * c['relative']:.2f} % | "
                 f"{l['mean']:.4g} | {d['mean']:.4g} | {100 * d['relative']:.2f} % |")
hp = harvard["phonemes"]
hpauses = sum(p["value"] == "sil" for p in hp)
lines += [
    "",
    f"Harvard sentences, list 1 (`assets/speech/harvard-list1.txt`, 10 sentences, "
    f"{harvard['metadata']['duration']:.1f} s, {len(hp) - hpauses} phonemes, {hpauses} pauses), cubic:",
    "",
    "| m | mean | max | of motion |",
    "|---:|---:|---:|---:|",
]
for m in ms:
    p = point(harvard, m)
    lines.append(f"| {m} | {p['mean']:.4g} | {p['max']:.3g} | {100 * p['relative']:.2f} % |")
lines += [
    "",
    f"The sentence of the picture, \"{sentence}\" ({said['metadata']['duration']:.2f} s, cubic):",
    "",
    "| m | mean | max | of motion |",
    "|---:|---:|---:|---:|",
]
for m in ms:
    p = point(said, m)
    lines.append(f"| {m} | {p['mean']:.4g} | {p['max']:.3g} | {100 * p['relative']:.2f} % |")
lines += [
    "",
    f"(squared distances in the sample's units, area weights; espeak-ng {espeak.split('+')[0] or '?'}, "
    f"en-us, 175 wpm, 60 fps.)",
    "<!-- speech-figures:end -->",
]
doc = open("docs/speech.md").read()
block = "\n".join(lines)
new, count = re.subn(r"<!-- speech-figures:begin.*?<!-- speech-figures:end -->", lambda _: block, doc, flags=re.S)
if count != 1:
    sys.exit("docs/speech.md: no speech-figures block to replace")
open("docs/speech.md", "w").write(new)
print("\n".join(lines))
PY
