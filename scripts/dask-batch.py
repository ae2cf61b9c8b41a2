#!/usr/bin/python3
"""Runs a `visemelab batch` jobs file on Dask distributed workers with the Python package.

    scripts/dask-batch.py JOBS.jsonl --out DIR [--scheduler tcp://host:port | --workers N]

The lines are cut into chunks (a few per worker thread, not one task per line: a task costs a
scheduler round trip); each chunk runs visemelab.run_jobs on a worker, whose process keeps its loaded
projects and avatars between chunks. The result lines are written in line order to the standard
output (or --results FILE), exactly as `visemelab batch` writes them; the exit status is 0 only when
every job succeeded. Outputs go to DIR, which every worker must see at the same path (a shared
filesystem on a cluster); relative paths in the jobs are read from the jobs file's folder, so on a
cluster name the jobs file by a path every worker resolves alike (absolute, on the shared filesystem).

Without --scheduler a LocalCluster of --workers processes (one thread each) runs on this machine.
The workers import visemelab from their own PYTHONPATH (a build tree: build/release/app/python).
"""

import argparse
import json
import os
import pathlib
import sys
import time


def chunks_of(lines, size):
    """(first line number, lines) pieces of `size` lines, numbered from 1 as the jobs file's lines."""
    return [(start + 1, lines[start:start + size]) for start in range(0, len(lines), size)]


def run_chunk(first_line, lines, out_dir, jobs_file):
    """One task: a chunk of lines, one job after the other in this worker thread (Dask runs the
    threads and processes in parallel), through the worker process's cached context."""
    import visemelab

    return visemelab.run_jobs(lines, out_dir, jobs_file, first_line=first_line, threads=1)


def warm_worker():
    """Imports the package on a worker (the first import loads espeak-ng's data and the module)."""
    import visemelab

    return visemelab.__version__


# Dask's nanny starts workers with MALLOC_TRIM_THRESHOLD_=65536 (distributed.nanny.pre-spawn-environ),
# which turns off glibc's adaptive mmap threshold: every block over 128 KiB (a sentence's audio, its
# tracks) is then mapped and unmapped afresh, page faults included. On 2 workers x 1 thread that made
# the same jobs about 30 % slower than without (scripts/dask-bench.py, docs/batch.md "Dask").
TRIM_VARIABLE = "MALLOC_TRIM_THRESHOLD_"


def local_cluster(workers, threads_per_worker):
    """A LocalCluster whose workers keep glibc's adaptive malloc thresholds."""
    import dask
    from dask.distributed import LocalCluster

    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ"))
    environ.pop(TRIM_VARIABLE, None)
    with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}):
        return LocalCluster(n_workers=workers, threads_per_worker=threads_per_worker, processes=True,
                            dashboard_address=None)


def worker_trim_setting():
    import os

    return os.environ.get(TRIM_VARIABLE)


def warn_about_trimming(client):
    """Says when workers (of a scheduler started elsewhere) run with Dask's malloc trimming."""
    trimmed = sorted(w for w, v in client.run(worker_trim_setting).items()
                     if v is not None and v.isdigit() and int(v) < (1 << 20))
    if trimmed:
        print(f"dask-batch: {len(trimmed)} workers run with {TRIM_VARIABLE} set (Dask's default 65536 costs "
              "about 30 %): start them as docs/batch.md says", file=sys.stderr)


def chunk_size_for(line_count, slots, requested):
    if requested > 0:
        return requested
    # About 4 chunks per worker thread: large enough that the per-task cost (a few ms) is noise, small
    # enough that the last chunks balance the load across workers.
    return max(1, -(-line_count // (4 * max(1, slots))))


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("jobs", help="JOBS.jsonl: one `visemelab batch` job per line")
    parser.add_argument("--out", required=True, help="Output folder (shared by every worker)")
    parser.add_argument("--scheduler", help="Address of a running dask scheduler (tcp://host:8786)")
    parser.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                        help="Without --scheduler: local worker processes (default: one per core)")
    parser.add_argument("--threads-per-worker", type=int, default=1, help="Local workers' threads (default 1)")
    parser.add_argument("--chunk", type=int, default=0, help="Lines per task (default: about 4 tasks per thread)")
    parser.add_argument("--results", help="Write the result lines here instead of the standard output")
    parser.add_argument("--timings", help="Write {startup_s, run_s, jobs, tasks} as JSON here")
    args = parser.parse_args(argv)

    from dask.distributed import Client

    # Named as given (the result lines name it as `visemelab batch` does); the workers resolve it.
    jobs_file = args.jobs
    lines = pathlib.Path(jobs_file).read_text(encoding="utf-8").splitlines()
    out_dir = args.out

    started = time.perf_counter()
    cluster = None
    if args.scheduler:
        client = Client(args.scheduler)
    else:
        cluster = local_cluster(args.workers, args.threads_per_worker)
        client = Client(cluster)
    try:
        client.run(warm_worker)
        warn_about_trimming(client)
        slots = sum(client.nthreads().values())
        startup = time.perf_counter() - started

        started = time.perf_counter()
        pieces = chunks_of(lines, chunk_size_for(len(lines), slots, args.chunk))
        futures = [client.submit(run_chunk, first, chunk, out_dir, jobs_file, pure=False)
                   for first, chunk in pieces]
        results = [line for chunk in client.gather(futures) for line in chunk]
        run = time.perf_counter() - started
    finally:
        client.close()
        if cluster is not None:
            cluster.close()

    text = "".join(line + "\n" for line in results)
    if args.results:  # atomically, as every output of VisemeLab
        results_file = pathlib.Path(args.results)
        partial = results_file.with_name(results_file.name + ".partial")
        partial.write_text(text, encoding="utf-8")
        os.replace(partial, results_file)
    else:
        sys.stdout.write(text)
    if args.timings:
        pathlib.Path(args.timings).write_text(json.dumps(
            {"startup_s": startup, "run_s": run, "jobs": len(lines), "tasks": len(pieces), "slots": slots}))
    print(f"dask-batch: {len(lines)} lines in {len(pieces)} tasks on {slots} worker threads: "
          f"{run:.2f} s (cluster start-up {startup:.2f} s, not counted)", file=sys.stderr)
    failed = sum(1 for line in results if json.loads(line).get("status") == "error")
    return 0 if failed == 0 else 3


if __name__ == "__main__":
    sys.exit(main())
