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
#   scripts/bench-frame.sh [--before OLD_EDITOR] [frames timed per run, default 120] [rounds, default 1]
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

# One editor run inside its own Xvfb, driven as tests/ui/GuiDriver does: every step waits until
# the editor's probe (a JSON file it writes every frame, in both modes and both editors alike) shows
# the previous one arrived. Frames must be running (a press while the project still loads is lost),
# the pointer seen over the slider, then the press seen with the slider active; only then the drag
# starts (and the timed frames: idle runs wait for the same frames, without the mouse).
DRIVER = r"""
editor=$1; x0=$2; x1=$3; y=$4; started=$5; probe=$6; shift 6
# Waits (at most 120 s, and while the editor runs) until the probe satisfies a Python condition on
# d (the probe's JSON).
until_probe() {
  python3 - "$probe" "$1" $pid <<'WAIT'
import json, os, sys, time
path, condition, pid = sys.argv[1], sys.argv[2], int(sys.argv[3])
end = time.time() + 120

def running():  # an editor that exited stays a zombie until the driver waits for it
    try:
        with open("/proc/%d/stat" % pid) as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False

while time.time() < end and running():
    try:
        with open(path) as f:
            d = json.load(f)
        if eval(condition):
            sys.exit(0)
    except (OSError, ValueError, KeyError):
        pass
    time.sleep(0.05)
sys.exit("bench-frame: the editor never showed " + condition)
WAIT
}
frame() { python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["frame"])' "$probe"; }
rm -f "$probe"
"$editor" "$@" & pid=$!
window=$(timeout 60 xdotool search --sync --pid $pid | head -1)
until_probe 'd["frame"] >= 3' # the project is loaded and the panel laid out
xdotool windowfocus --sync $window 2>/dev/null || true
if [[ $x0 != none ]]; then
  xdotool mousemove --window $window $x0 $y
  until_probe "abs(d['input']['x'] - $x0) < 1 and abs(d['input']['y'] - $y) < 1"
  f=$(frame); until_probe "d['frame'] >= $f + 3" # hovered for some frames before the press
  xdotool mousedown 1
  until_probe "d['input']['buttons'][0] and d['active_control']"
else
  f=$(frame); until_probe "d['frame'] >= $f + 8" # about the frames a drag run waits
fi
date +%s.%N > "$started"
while [[ $x0 != none ]] && kill -0 $pid 2>/dev/null; do
  # A random point each time: whatever number of moves lands between two frames, the next frame
  # almost surely sees a new slider value.
  xdotool mousemove --window $window $((x0 + RANDOM % (x1 - x0))) $y 2>/dev/null || true
done
wait $pid
"""

# Frames an editor renders before the drag starts (the steps above): the editor stops after a frame
# count, so each run gets these on top of the frames to time.
PRESS_FRAMES = 150

def run(editor, drag, frame_count, extra=(), env=None):
    points = [str(v) for v in drag] if drag else ["none", "none", "none"]
    points += [os.path.join(work, "started"), os.path.join(work, "probe.json")]
    subprocess.run(xvfb + ["bash", "-c", DRIVER, "driver", editor] + points + base +
                   ["--frames", str(frame_count)] + list(extra), check=True, stdout=subprocess.DEVNULL,
                   env=env)

def probe(editor, drag, frame_count):
    path = os.path.join(work, "probe.json")
    run(editor, drag, frame_count, ["--probe", path])
    with open(path) as f:
        return json.load(f)

# Where each editor draws the slider (the panels' layout differs between versions).
editors = {"after": after} if not before else {"before": before, "after": after}
drags, starts = {}, {}
for name, editor in editors.items():
    starts[name] = probe(editor, None, 40)
    slider = next(c for c in starts[name]["controls"] if c["kind"] == "slider" and c["label"] == "jaw_open")
    drags[name] = (int(slider["x"] + 60), int(slider["x"] + slider["width"] - 140),
                   int(slider["y"] + slider["height"] / 2))
    print("%s: jaw_open slider at %s" % (name, drags[name]), file=sys.stderr)
vertices = starts["after"]["document"]["face_view"]["skin_triangles"]

times = {(name, mode): [] for name in editors for mode in ("drag", "idle")}
unmoved_runs = []
for _ in range(rounds):
    for name, editor in editors.items():  # interleaved: a change of machine load hits both editors
        for mode in ("drag", "idle"):
            out = os.path.join(work, "frames-%s-%s.txt" % (name, mode))
            env = dict(os.environ, LD_PRELOAD=os.path.join(work, "frame-clock.so"), FRAME_CLOCK_OUT=out)
            # Every run keeps the probe (a 16 kB JSON a frame, in both editors and modes alike): the
            # driver waits on it, and it proves that the slider moved.
            probed = ["--probe", os.path.join(work, "probe.json")]
            run(editor, drags[name] if mode == "drag" else None, PRESS_FRAMES + frames, probed, env)
            if mode == "drag":
                with open(os.path.join(work, "probe.json")) as f:
                    moved = json.load(f)["document"]["parameters"]["jaw_open"]
                unmoved = starts[name]["document"]["parameters"]["jaw_open"]
                # A run whose slider did not move timed a held mouse, not a drag: counted and
                # reported under the table.
                if moved == unmoved:
                    unmoved_runs.append(name)
                print("%s: jaw_open %g after the drag (%s)" % (name, moved, "moved" if moved != unmoved
                      else "DID NOT MOVE"), file=sys.stderr)
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
if unmoved_runs:
    print("NOT VALID: the slider did not move in %d drag runs (%s)" % (len(unmoved_runs), ", ".join(unmoved_runs)))
PY
