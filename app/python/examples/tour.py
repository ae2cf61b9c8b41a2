#!/usr/bin/python3
"""A tour of the visemelab package (no notebook needed):

    PYTHONPATH=build/release/app/python app/python/examples/tour.py [AVATAR.glb]

Reduces the bundled sample's visemes to 5 keys, says a sentence with it (track + WAV), reduces an
avatar when one is given (bytes in, bytes out), and runs two batch jobs. Writes into a temporary folder
and prints what it made.
"""

import json
import pathlib
import sys
import tempfile

import numpy as np

import visemelab

ROOT = pathlib.Path(__file__).resolve().parents[3]
SAMPLE = ROOT / "assets" / "sample"


def main():
    out = pathlib.Path(tempfile.mkdtemp(prefix="visemelab-tour-"))

    # 1. A viseme set from mesh files (or VisemeSet(neutral, triangles, {name: positions}) from arrays).
    visemes = visemelab.load_visemes(folder=SAMPLE)
    print(f"{len(visemes)} visemes of {visemes.neutral.shape[0]} vertices: {', '.join(visemes.names)}")
    result = visemelab.reduce_visemes(visemes, m=5, weights="area", pin=["PP"])
    print("groups:", " | ".join("+".join(g) for g in result["groups"]), "resting:", result["resting"])
    print("cost for 1..5 keys:", ", ".join(f"{c:.3g}" for c in result["cost_curve"]))
    key = result["keys"][0]
    print(f"key {key['name']}: positions {key['positions'].shape}, "
          f"moves up to {np.abs(key['positions'] - result['neutral']).max():.3g} model units")

    # 2. A sentence: the same bytes `visemelab say` writes with --out track.json --wav speech.wav.
    said = visemelab.say("Reduced visemes still speak clearly.", project=SAMPLE / "sample.vlproj",
                         track_name=out / "track.json", wav_name=out / "speech.wav")
    (out / "track.json").write_text(said["track"])
    (out / "speech.wav").write_bytes(said["wav"])
    error = json.loads(said["track"])["error"]
    print(f"said it: {len(said['wav'])} bytes of WAV, utterance error {100 * error['relative']:.1f} % of the motion")

    # 3. An avatar, bytes in and out (as `visemelab avatar reduce AVATAR -m 6`).
    if len(sys.argv) > 1:
        glb, report = visemelab.reduce_avatar(pathlib.Path(sys.argv[1]).read_bytes(), m=6, name=sys.argv[1])
        (out / "reduced.glb").write_bytes(glb)
        print(f"avatar reduced: {len(glb)} bytes, cost {json.loads(report)['cost']:.3g}")

    # 4. Jobs of a JOBS.jsonl file, as `visemelab batch` runs them (results in line order).
    lines = [json.dumps({"id": "hello", "command": "say", "text": "Hello there.",
                         "project": str(SAMPLE / "sample.vlproj"), "wav": True}),
             json.dumps({"id": "oops", "command": "say", "text": "Hi.", "project": "missing.vlproj"})]
    for line in visemelab.run_jobs(lines, str(out / "jobs"), str(out / "jobs.jsonl")):
        print("job:", line)

    # 5. Bad input names its culprit.
    try:
        visemelab.reduce_visemes(visemes, m=3, pin=["nosuch"])
    except visemelab.InputError as e:
        print(f"InputError at {e.culprit!r}: {e}")
    print("outputs in", out)


if __name__ == "__main__":
    main()
