"""Process CPU time (user + sys of the process and its threads) for the benchmark scripts."""
import os
import subprocess
import sys


def cpu_seconds(args, env=None, stdin=None):
    """`stdin`: bytes fed to the process's standard input."""
    process = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env,
                               stdin=subprocess.PIPE if stdin is not None else subprocess.DEVNULL)
    if stdin is not None:
        process.stdin.write(stdin)
        process.stdin.close()
    _, status, usage = os.wait4(process.pid, 0)
    if status != 0:
        sys.exit("failed: %s\n%s" % (" ".join(args), process.stderr.read().decode()))
    return usage.ru_utime + usage.ru_stime
