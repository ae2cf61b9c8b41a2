#!/usr/bin/env bash
# Issue 33's large-mesh goal: `visemelab reduce` of 1,000,000 vertices x 16 visemes (binary PLY,
# float32 x,y,z), m = 10, against the physical floor of the same bytes measured in the same run, and
# its max RSS against the input's float positions (17 meshes x V x 12 bytes).
# The floor is built outside VisemeLab: `cat` of every input file to /dev/null plus a C writer
# (tests/bench/floor/write_floor.c, compiled here with cc) writing files of the sizes `reduce` wrote,
# each fsynced. Rounds alternate process and floor; outputs go into an emptied folder each time (a
# first export), inputs stay in the page cache for both. Wall time and max RSS from /usr/bin/time.
# Usage: scripts/bench-large-mesh.sh [runs=3] [vertices=1000000] [visemes=16] [path/to/visemelab]
# The set is generated once into ${VISEMELAB_LARGE_DIR:-/tmp/visemelab-large-V-N} (650 MB at 1M x 16).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
vertices=${2:-1000000}
visemes=${3:-16}
cli=$(realpath "${4:-build/release/app/visemelab}")
[ -x "$cli" ] || { echo "no $cli: build first (scripts/build.sh)" >&2; exit 2; }
data=${VISEMELAB_LARGE_DIR:-/tmp/visemelab-large-$vertices-$visemes}
[ -f "$data/v$(printf %02d $((visemes - 1))).ply" ] || python3 scripts/generate-large-ply.py "$data" "$vertices" "$visemes"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cc -O2 -o "$work/write_floor" tests/bench/floor/write_floor.c
python3 - "$runs" "$cli" "$data" "$work" <<'PY'
import glob, os, shutil, statistics, subprocess, sys
runs, cli, data, work = int(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
inputs = sorted(glob.glob(os.path.join(data, "*.ply")))
out, floor_out = os.path.join(work, "out"), os.path.join(work, "floor")

def timed(argv):
    """Wall seconds and max RSS (bytes) of one process, from GNU time."""
    r = subprocess.run(["/usr/bin/time", "-f", "%e %M"] + argv, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True, check=True)
    wall, rss_kb = r.stderr.strip().splitlines()[-1].split()
    return float(wall), int(rss_kb) * 1024

def fresh(folder):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)

vertex_count = None
with open(inputs[0], "rb") as f:
    for line in f:
        if line.startswith(b"element vertex"):
            vertex_count = int(line.split()[2])
            break
float_positions = len(inputs) * vertex_count * 12
process, floor, rss = [], [], []
for _ in range(runs):
    fresh(out)
    wall, peak = timed([cli, "reduce", "--visemes", data, "-m", "10", "--out", out])
    process.append(wall)
    rss.append(peak)
    sizes = [str(os.path.getsize(os.path.join(out, name))) for name in sorted(os.listdir(out))]
    fresh(floor_out)
    read_wall, _ = timed(["sh", "-c", 'cat "$@" > /dev/null', "cat"] + inputs)
    write_wall, _ = timed([os.path.join(work, "write_floor"), floor_out] + sizes)
    floor.append(read_wall + write_wall)

def mmm(values, fmt):
    return ", ".join(fmt % v for v in (min(values), statistics.median(values), max(values)))

in_bytes = sum(os.path.getsize(p) for p in inputs)
out_bytes = sum(int(s) for s in sizes)
print("%d meshes of %d vertices: %.0f MB in, %.0f MB out (%d files); %d rounds" %
      (len(inputs), vertex_count, in_bytes / 1e6, out_bytes / 1e6, len(sizes), runs))
print("process wall (min, median, max):       " + mmm(process, "%.2f s"))
print("floor: cat + C writer with fsync:      " + mmm(floor, "%.2f s"))
print("process / floor per round:             " + mmm([p / f for p, f in zip(process, floor)], "%.2f"))
print("max RSS:                               " + mmm([r / 1e6 for r in rss], "%.0f MB"))
print("max RSS / input float positions (%.0f MB): %s" %
      (float_positions / 1e6, mmm([r / float_positions for r in rss], "%.2f")))
PY
