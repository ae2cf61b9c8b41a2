#!/usr/bin/env bash
# The fixed cost of a call (issue 33 pt 3): `visemelab --help` (the launcher, app/cli/Launcher.c)
# against /bin/true and against the commands' own --help (visemelab-cli, which loads espeak-ng, CLP,
# Draco, TBB, libstdc++), process CPU time and wall time over interleaved runs: min / median / max
# and the ratios to /bin/true measured in the same run. Goal: launcher <= 2x /bin/true.
#   scripts/bench-startup.sh [runs]   (default 300; build/release must be built)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-300}
app=build/release/app
/usr/bin/python3 - "$runs" "$app" <<'PY'
import os, statistics, subprocess, sys, time
runs, app = int(sys.argv[1]), sys.argv[2]
programs = {"/bin/true": ["/bin/true"], "visemelab --help": [app + "/visemelab", "--help"],
            "visemelab-cli --help": [app + "/visemelab-cli", "--help"]}
cpu = {name: [] for name in programs}
wall = {name: [] for name in programs}
for _ in range(runs):
    for name, args in programs.items():  # interleaved: a change of machine speed hits all three
        start = time.perf_counter()
        process = subprocess.Popen(args, stdout=subprocess.DEVNULL)
        _, status, usage = os.wait4(process.pid, 0)
        wall[name].append(1e3 * (time.perf_counter() - start))
        cpu[name].append(1e3 * (usage.ru_utime + usage.ru_stime))
        assert status == 0, name
def row(name, values):
    return "%.2f / %.2f / %.2f ms" % (min(values), statistics.median(values), max(values))
print("%d interleaved runs each; min / median / max" % runs)
for name in programs:
    ratio_wall = statistics.median(wall[name]) / statistics.median(wall["/bin/true"])
    ratio_cpu = statistics.median(cpu[name]) / max(statistics.median(cpu["/bin/true"]), 1e-9)
    print("%-22s wall %s (%.2fx /bin/true)   CPU %s (%.2fx)" % (name, row(name, wall[name]), ratio_wall,
                                                               row(name, cpu[name]), ratio_cpu))
PY
