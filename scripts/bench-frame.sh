#!/usr/bin/env bash
# Editor frame CPU while a face slider is dragged on a face of about 100,000 vertices (issue 31).
# The real editor runs under Xvfb on a project whose deformable face has a 308-cell (u,v) domain
# (`visemelab face build --resolution 308` on the bundled face's skin: 95,576 vertices, its 15 Oculus
# visemes; 316 would make a project JSON over the 128 MiB limit), the Deformation panel open.
# xdotool holds the jaw_open slider and swings the pointer between two points as fast as it can (the
# editor's --drag presses at frame 1, where the panel takes no click yet, so it moves no slider).
# scripts/frame-clock.c, preloaded, reads the clocks at every buffer swap, so an older editor with no
# hook of its own is timed the same way. Each editor runs `drag` and `idle` (the same frames, no
# mouse), interleaved round by round; frame times are min / median / max over the frames of every
# round that start after the press (or, idle, the same moment), in ms of process CPU (all threads: UI,
# background jobs, the GL driver's), main-thread CPU and wall.
#   scripts/bench-frame.sh [--before OLD_EDITOR] [frames per run, default 120] [rounds, default 1]
# Needs build/release/ui/visemelab-editor, build/release/app/visemelab, xvfb-run, xdotool, cc.
set -euo pipefail
cd "$(dirname "$0")/.."
before=""
if [[ ${1:-} == --before ]]; then
  before=$(realpath "$2")
  shift 2
fi
frames=${1:-120}
rounds=${2:-1}
editor=$(realpath build/release/ui/visemelab-editor)
cli=build/release/app/visemelab
work=${BENCH_FRAME_DIR:-/tmp/visemelab-bench-frame}
mkdir -p "$work"

cc -O2 -Wall -Wextra -Werror -shared -fPIC -o "$work/frame-clock.so" scripts/frame-clock.c -ldl

# The large face, made once: the bundled face's skin as "my own mesh", rebuilt on a fine domain.
project=$work/face100k.vlproj
if [[ ! -f $project ]]; then
  "$cli" visemes --face bundled --skin-only --resolution 48 --out "$work/skin" >/dev/null
  "$cli" face build "$work/skin/neutral.obj" --resolution 308 --out "$project" >/dev/null
fi

/usr/bin/python3 - "$work" "$project" "$frames" "$rounds" "$editor" "$before" <<'PY'
import json, os, statistics, subprocess, sys
work, project, frames, rounds, after, before = sys.argv[1:7]
frames, rounds = int(frames), int(rounds)
xvfb = ["xvfb-run", "-a", "-s", "-screen 0 1600x1000x24"]
base = ["--project", project, "--panel", "Deformation", "--size", "1600", "1000",
        "--screenshot", os.path.join(work, "last.png")]

# One editor run inside its own Xvfb. With a drag, once the window's title names the project (the
# project is loaded, frames are running) the pointer presses on the slider and moves along it until
# the editor exits after its frames.
DRIVER = r"""
editor=$1; x0=$2; x1=$3; y=$4; started=$5; shift 5
"$editor" "$@" & pid=$!
window=$(timeout 60 xdotool search --sync --pid $pid | head -1)
until xdotool getwindowname $window 2>/dev/null | grep -q face100k; do
  kill -0 $pid 2>/dev/null || break; sleep 0.05; done
# As tests/ui/GuiDriver does: the window focused and the pointer over the slider some frames before
# the press (a press in the frame the pointer arrives in activates nothing).
xdotool windowfocus --sync $window 2>/dev/null || true
[[ $x0 != none ]] && xdotool mousemove --window $window $x0 $y 2>/dev/null
sleep 2
[[ $x0 != none ]] && xdotool mousedown 1 2>/dev/null && sleep 0.5 # the press seen before any move
date +%s.%N > "$started" # idle runs too: the same frames are measured
while [[ $x0 != none ]] && kill -0 $pid 2>/dev/null; do
  # A random point each time: whatever number of moves lands between two frames, the next frame
  # almost surely sees a new slider value.
  xdotool mousemove --window $window $((x0 + RANDOM % (x1 - x0))) $y 2>/dev/null || true
done
wait $pid
"""

def run(editor, drag, frame_count, extra=(), env=None):
    points = [str(v) for v in drag] if drag else ["none", "none", "none"]
    points.append(os.path.join(work, "started"))
    subprocess.run(xvfb + ["bash", "-c", DRIVER, "driver", editor] + points + base +
                   ["--frames", str(frame_count)] + list(extra), check=True, stdout=subprocess.DEVNULL,
                   env=env)

def probe(editor, drag, frame_count):
    path = os.path.join(work, "probe.json")
    run(editor, drag, frame_count, ["--probe", path])
    with open(path) as f:
        return json.load(f)

# Where the slider is.
start = probe(after, None, 3)
slider = next(c for c in start["controls"] if c["kind"] == "slider" and c["label"] == "jaw_open")
drag = (int(slider["x"] + 60), int(slider["x"] + slider["width"] - 140), int(slider["y"] + slider["height"] / 2))
editors = {"after": after} if not before else {"before": before, "after": after}
vertices = start["document"]["face_view"]["skin_triangles"]

times = {(name, mode): [] for name in editors for mode in ("drag", "idle")}
for _ in range(rounds):
    for name, editor in editors.items():  # interleaved: a change of machine load hits both editors
        for mode in ("drag", "idle"):
            out = os.path.join(work, "frames-%s-%s.txt" % (name, mode))
            env = dict(os.environ, LD_PRELOAD=os.path.join(work, "frame-clock.so"), FRAME_CLOCK_OUT=out)
            # The drag runs keep the probe (a 16 kB JSON a frame, in both editors alike) to prove that
            # the slider moved.
            probed = ["--probe", os.path.join(work, "probe.json")] if mode == "drag" else []
            run(editor, drag if mode == "drag" else None, frames, probed, env)
            if mode == "drag":
                with open(os.path.join(work, "probe.json")) as f:
                    moved = json.load(f)["document"]["parameters"]["jaw_open"]
                # Reported, not asserted: on this project the held slider has been seen not to move
                # (docs/performance.md, issue 31), and the table must say so rather than stop.
                print("%s: jaw_open %g after the drag (%s)" % (name, moved, "moved" if moved !=
                      start["document"]["parameters"]["jaw_open"] else "DID NOT MOVE"), file=sys.stderr)
            with open(out) as f:
                rows = [[float(x) for x in line.split()] for line in f.readlines()[1:]]
            with open(os.path.join(work, "started")) as f:
                started = float(f.read())
            times[(name, mode)] += [row[:3] for row in rows if row[3] - row[2] * 1e-3 > started]

def cell(values):
    return "%.1f / %.1f / %.1f" % (min(values), statistics.median(values), max(values))
print("%d rounds x %d frames, 1600x1000 window, %d skin triangles in the face view; load average %s"
      % (rounds, frames, vertices, " ".join(f"{x:.2f}" for x in os.getloadavg())))
print("| editor | mode | frames | process CPU ms | main-thread CPU ms | wall ms |")
print("|---|---|---|---|---|---|")
for (name, mode), rows in times.items():
    columns = list(zip(*rows))
    print("| %s | %s | %d | %s | %s | %s |" % (name, mode, len(rows), cell(columns[0]), cell(columns[1]),
                                              cell(columns[2])))
if before:
    for mode in ("drag", "idle"):
        ratio = [statistics.median(list(zip(*times[("before", mode)]))[k]) /
                 statistics.median(list(zip(*times[("after", mode)]))[k]) for k in range(3)]
        print("%s: before / after medians: process CPU %.2fx, main thread %.2fx, wall %.2fx"
              % (mode, *ratio))
PY
