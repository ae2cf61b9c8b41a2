#!/usr/bin/env bash
# Prints the table of avatar kinds of docs/avatars.md: for each generated fixture (and the 30k-vertex
# benchmark avatar), vertices, viseme vertices, meshes carrying visemes, targets, and the process
# wall time of `visemelab avatar reduce` (median of 5 runs). Needs a release build.
set -euo pipefail
cd "$(dirname "$0")/.."
cli=build/release/app/visemelab
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
build/release/tests/gltf/write_avatar_fixtures "$dir" --bench >/dev/null
python3 - "$cli" "$dir" <<'PY'
import json, os, statistics, subprocess, sys, time
cli, folder = sys.argv[1], sys.argv[2]
kinds = [("rpm_plain", "Ready Player Me-like, skinned, float", []),
         ("rpm_quantised", "… KHR_mesh_quantization (unskinned)", []),
         ("rpm_meshopt", "… EXT_meshopt_compression", []),
         ("rpm_sparse", "… sparse targets", []),
         ("rpm_draco", "… KHR_draco_mesh_compression (head)", []),
         ("vroid_vrm0", "VRoid-like, VRM 0.x", ["--targets", "Fcl_MTH_[AIUEO]"]),
         ("vroid_vrm1", "VRoid-like, VRM 1.0", ["--targets", "Fcl_MTH_[AIUEO]"]),
         ("rpm_30k", "Ready Player Me-like, 30k viseme vertices (benchmark)", [])]
print("| avatar | file vertices | viseme vertices | meshes with visemes | targets (visemes) | m | file KB in → out | reduce (s) |")
print("|---|---|---|---|---|---|---|---|")
for stem, title, extra in kinds:
    glb = os.path.join(folder, stem + ".glb")
    scan = os.path.join(folder, stem + ".json")
    subprocess.run([cli, "avatar", "inspect", glb, "--json", scan] + extra, check=True, stdout=subprocess.DEVNULL)
    report = json.load(open(scan))
    carriers = [m for m in report["meshes"] if m["carries_visemes"]]
    targets = sum(len(m["visemes"]) + len(m["ignored"]) for m in report["meshes"])
    m = 3 if stem.startswith("vroid") else 6
    out = os.path.join(folder, stem + "_out.glb")
    times = []
    for _ in range(5):
        start = time.perf_counter()
        subprocess.run([cli, "avatar", "reduce", glb, "--target", str(m), "--weights", "area", "--out", out] + extra,
                       check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - start)
    print("| %s | %s | %s | %d | %d (%d) | %d | %d → %d | %.3f |" % (
        title, f"{report['vertices']:,}", f"{report['viseme_vertices']:,}", len(carriers), targets,
        len(report["visemes"]), m, os.path.getsize(glb) // 1024, os.path.getsize(out) // 1024, statistics.median(times)))
PY
