#!/usr/bin/env bash
# The numbers of docs/phoneme-groups.md: the optimal groupings of the bundled ARPAbet phoneme set
# (sil + 39 phonemes, `visemelab visemes --set arpabet`) into p = 1..12 groups, weighted by the bundled
# en-us phoneme table, against the standard phoneme -> viseme maps used as groupings (Oculus 15,
# MPEG-4 15, Preston Blair / Rhubarb 9) under the same objective (`reduce --compare-map`).
#
#   scripts/phoneme-groups.sh [OUTDIR]     # needs a built build/release/app/visemelab
#
# Run 1: -m 12 with no time limit (every p = 1..12 solved to a proof; its wall and CPU time are the
# certification time). Run 2: -m 15 with a 60 s limit, for the two 15-group maps (gap reported when the
# limit stops the proof).
set -euo pipefail
cd "$(dirname "$0")/.."
cli=build/release/app/visemelab
out=${1:-$(mktemp -d)}
mkdir -p "$out"
table=assets/phonemes/en-us_frequencies.csv
maps=(assets/phonemes/map_oculus.csv assets/phonemes/map_mpeg4.csv assets/phonemes/map_rhubarb.csv)
compare=()
for map in "${maps[@]}"; do compare+=(--compare-map "$map"); done

"$cli" visemes --set arpabet --out "$out/arpabet"
python3 - "$cli" "$out" "$table" "${compare[@]}" <<'PY'
import json, os, resource, subprocess, sys, time
cli, out, table, compare = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]

def run(m, limit, tag):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    args = [cli, "reduce", "--visemes", os.path.join(out, "arpabet"), "--freq-file", table, "-m", str(m),
            "--time-limit", str(limit), "--out", os.path.join(out, tag)] + compare
    print("$", " ".join(args))
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime
    report = json.load(open(os.path.join(out, tag, "report.json")))
    print(f"  process: {wall:.1f} s wall, {cpu:.1f} s CPU (all threads); reduce {report['timing_ms']['reduce'] / 1000:.1f} s")
    return report

def pairs(groups):
    return {(a, b) for g in groups for a in g for b in g if a < b}

full = run(12, 0, "m12")
wide = run(15, 60, "m15")
curve = full["cost_curve"] + wide["cost_curve"][12:]
proved = full["optimal_curve"] + wide["optimal_curve"][12:]
bound = full["lower_bound_curve"] + wide["lower_bound_curve"][12:]
groupings = full["groups_curve"] + wide["groups_curve"][12:]
print("\np   cost      proved  gap")
for p in range(1, 16):
    c, lb = curve[p - 1], bound[p - 1]
    print(f"{p:<3} {c:<9.4g} {str(proved[p - 1]):<7} {0 if proved[p - 1] else 100 * (c - lb) / c:.2f} %")
print()
for p in range(8, 13):
    print(f"optimal p = {p}: " + " | ".join(" ".join(g) for g in groupings[p - 1]))
print()
for entry in wide["compared_maps"]:
    groups = list(entry["grouping"].values())
    p = entry["groups"]
    best, state = curve[p - 1], "optimum" if proved[p - 1] else "best found"
    print(f"{os.path.basename(entry['map'])}: {p} groups, cost {entry['cost']:.4g}; {state} for {p} groups "
          f"{best:.4g} (map +{100 * (entry['cost'] / best - 1):.0f} %)")
    print("  groups: " + " | ".join(f"{k}: {' '.join(v)}" for k, v in entry["grouping"].items()))
    fewest = min(q for q in range(1, 16) if curve[q - 1] <= entry["cost"])
    print(f"  the optimum reaches that cost with p = {fewest} groups")
    mine, theirs = pairs(groupings[p - 1]), pairs(groups)
    print(f"  same-group pairs vs the optimum for {p}: {len(mine & theirs)} shared, {len(theirs - mine)} only in "
          f"the map, {len(mine - theirs)} only in the optimum")
PY
