#!/usr/bin/python3
"""Throughput of a Dask LocalCluster (2 worker processes x 1 thread) against `visemelab batch` on the
same machine and the same jobs: N ten-word `say` sentences on the bundled sample project.

    PYTHONPATH=build/release/app/python scripts/dask-bench.py [--jobs 1000] [--repeats 5]

Each side runs the jobs file --repeats times into a fresh output folder (after one untimed run that
fills the speech cache, which both share); the cluster is started once and its start-up is reported
apart from the throughput. Prints min / median / max seconds and jobs per second of each side and the
ratio of the medians (the goal: Dask within 1.3x of batch).
"""

import argparse
import json
import os
import pathlib
import random
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "scripts"))

WORDS = ("the quick brown fox jumps over lazy dogs while seven bright yellow birds sing softly near "
         "an old stone bridge and children laugh under tall green trees every summer morning").split()


def write_jobs(folder, count, seed=34):
    rng = random.Random(seed)
    project = ROOT / "assets" / "sample" / "sample.vlproj"
    jobs = folder / "jobs.jsonl"
    with jobs.open("w") as out:
        for i in range(count):
            text = " ".join(rng.choice(WORDS) for _ in range(10)).capitalize() + "."
            out.write(json.dumps({"id": f"s{i:05d}", "command": "say", "text": text,
                                  "project": str(project), "wav": True}) + "\n")
    return jobs


def summary(name, times, jobs):
    median = statistics.median(times)
    print(f"{name:>22}: min {min(times):6.2f} s, median {median:6.2f} s, max {max(times):6.2f} s "
          f"({jobs / median:6.1f} jobs/s)")
    return median


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--jobs", type=int, default=1000)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--chunk", type=int, default=0, help="Lines per Dask task (default: the runner's)")
    parser.add_argument("--trim", action="store_true",
                        help="Keep Dask's MALLOC_TRIM_THRESHOLD_=65536 in the workers (what it costs)")
    parser.add_argument("--cli", default=str(ROOT / "build" / "release" / "app" / "visemelab"))
    args = parser.parse_args()

    from dask.distributed import Client, LocalCluster

    dask_batch = __import__("dask-batch")
    with tempfile.TemporaryDirectory(prefix="dask-bench-") as tmp:
        tmp = pathlib.Path(tmp)
        os.environ["VISEMELAB_CACHE_DIR"] = str(tmp / "cache")  # inherited by the workers
        jobs = write_jobs(tmp, args.jobs)
        lines = jobs.read_text().splitlines()

        batch_results = []
        # The nanny leaks its pre-spawn variables into this process (--trim): not into the batch runs.
        batch_env = {k: v for k, v in os.environ.items() if k != dask_batch.TRIM_VARIABLE}

        def batch_once(out):
            started = time.perf_counter()
            done = subprocess.run([args.cli, "batch", str(jobs), "--out", str(out)], stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL, text=True, env=batch_env)
            elapsed = time.perf_counter() - started
            if done.returncode not in (0, 3):  # 3: some jobs' input refused; they are errors on both sides
                raise RuntimeError(f"visemelab batch failed ({done.returncode})")
            batch_results.append(done.stdout)
            return elapsed

        batch_once(tmp / "warm")  # fills the speech cache

        started = time.perf_counter()
        if args.trim:  # Dask's default: workers trim malloc at 64 KiB (for the comparison)
            cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                   dashboard_address=None)
        else:
            cluster = dask_batch.local_cluster(args.workers, 1)
        client = Client(cluster)
        client.run(dask_batch.warm_worker)
        startup = time.perf_counter() - started
        size = dask_batch.chunk_size_for(len(lines), args.workers, args.chunk)

        def dask_once(out):
            started = time.perf_counter()
            futures = [client.submit(dask_batch.run_chunk, first, chunk, str(out), str(jobs), pure=False)
                       for first, chunk in dask_batch.chunks_of(lines, size)]
            results = client.gather(futures)
            elapsed = time.perf_counter() - started
            text = "".join(line + "\n" for chunk in results for line in chunk)
            if text != batch_results[-1]:
                raise RuntimeError("the Dask run's result lines differ from visemelab batch's")
            return elapsed

        first = dask_once(tmp / "dask-first")
        # Alternated, so that both sides see the same load of a shared machine.
        batch_times, dask_times = [], []
        for r in range(args.repeats):
            batch_times.append(batch_once(tmp / f"batch{r}"))
            dask_times.append(dask_once(tmp / f"dask{r}"))
        client.close()
        cluster.close()

    errors = batch_results[-1].count('"status":"error"')
    print(f"{args.jobs} ten-word sentences ({errors} refused by both), {args.repeats} runs each, "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")
    b = summary("visemelab batch", batch_times, args.jobs)
    d = summary(f"dask {args.workers}x1{' trim' if args.trim else ''} (chunks {size})", dask_times, args.jobs)
    print(f"{'cluster start-up':>22}: {startup:6.2f} s (not in the runs); first run on fresh workers "
          f"{first:6.2f} s")
    print(f"dask / batch (medians): {d / b:.2f}x (goal <= 1.3x)")


if __name__ == "__main__":
    main()
