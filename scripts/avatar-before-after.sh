#!/usr/bin/env bash
# Prints the before/after table of docs/avatars.md: each generated avatar kind reduced with the keyed
# model of before issue 29 (`--rest key --closure none`) and with today's defaults (the rest free, the
# lips-closed viseme kept), both with --names original. Columns: how far the rest viseme moves (it
# should not), how far the lips-closed viseme moves against its own motion, the largest per-viseme
# error, and the file size in and out. Needs a release build.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=build/release/app/visemelab
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
build/release/tests/gltf/write_avatar_fixtures "$dir" >/dev/null
python3 - "$cli" "$dir" <<'PY'
import json, os, subprocess, sys
cli, folder = sys.argv[1], sys.argv[2]
kinds = [("rpm_plain", "Ready Player Me-like, float", 6, []),
         ("rpm_quantised", "Ready Player Me-like, KHR_mesh_quantization", 6, []),
         ("rpm_meshopt", "Ready Player Me-like, EXT_meshopt_compression", 6, []),
         ("vroid_vrm0", "VRoid-like, VRM 0.x, Fcl_MTH_*", 3, ["--targets", "Fcl_MTH_*"])]
models = [("before (rest is a key)", ["--rest", "key", "--closure", "none"]), ("after (defaults)", [])]
print("| avatar | m | model | rest viseme moves | lips-closed viseme moves | largest viseme error | resting | KB in → out |")
print("|---|---|---|---|---|---|---|---|")
for stem, title, m, extra in kinds:
    glb = os.path.join(folder, stem + ".glb")
    for label, flags in models:
        out, report = os.path.join(folder, "out.glb"), os.path.join(folder, "report.json")
        subprocess.run([cli, "avatar", "reduce", glb, "--target", str(m), "--out", out, "--report", report]
                       + extra + flags, check=True, stdout=subprocess.DEVNULL)
        r = json.load(open(report))
        motion = {x["viseme"]: x for x in r.get("viseme_motion", [])}
        def moves(name):
            if name not in motion:
                return "–"
            x = motion[name]
            return "%.1f of %.1f mm" % (x["after_mm"], x["before_mm"])
        rest = r["rest"].get("viseme") or "–"
        closure = next((v for v in ("viseme_PP", "PP") if v in motion), None)
        worst = max(r["viseme_errors"]["visemes"], key=lambda e: e["max"])
        print("| %s | %d | %s | %s | %s | %.1f mm (%s) | %s | %d → %d |" % (
            title, m, label, (rest + " " + moves(rest)) if rest != "–" else "no rest viseme",
            (closure + " " + moves(closure)) if closure else "no lips-closed viseme",
            worst["max"], worst["viseme"], ", ".join(r["rest"]["resting"]) or "none",
            os.path.getsize(glb) // 1024, os.path.getsize(out) // 1024))
PY
