"""Process CPU time (user + sys of the process and its threads) for the benchmark scripts."""
import os
import subprocess
import sys


def cpu_seconds(args):
    process = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(process.pid, 0)
    if status != 0:
        sys.exit("failed: %s\n%s" % (" ".join(args), process.stderr.read().decode()))
    return usage.ru_utime + usage.ru_stime
