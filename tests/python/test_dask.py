"""scripts/dask-batch.py on a Dask LocalCluster of 2 worker processes against `visemelab batch`: the
same result lines and the same output files, byte for byte."""

import json
import os
import pathlib
import subprocess
import sys
import unittest

from support import ASSETS, CLI, FIXTURES, ROOT, TempDirTest

PROJECT = ASSETS / "sample" / "sample.vlproj"


STAMPS = ".visemelab-batch"


def tree(folder):
    """{relative path: bytes} of every output under folder; the resume stamps by name only: they list
    the files read while the job ran, which jobs running beside it add to (core/common/InputRegistry.h
    InputWatch), so they differ between two runs of `visemelab batch` itself."""
    return {str(p.relative_to(folder)): b"" if STAMPS in p.parts else p.read_bytes()
            for p in sorted(folder.rglob("*")) if p.is_file()}


class DaskBatchTest(TempDirTest):
    def write_jobs(self):
        say = {"command": "say", "project": str(PROJECT)}
        jobs = [
            dict(say, id="hello", text="Hello there, how are you?", wav=True),
            dict(say, id="slow", text="The quick brown fox.", rate=120, wav=True),
            dict(say, id="gb", text="Jumps over the lazy dog.", voice="en-gb", format="rhubarb"),
            {"id": "missing", "command": "say", "text": "Hi.", "project": "nothere.vlproj"},
            {"id": "rpm4", "command": "avatar reduce", "input": str(FIXTURES / "rpm_plain.glb"), "m": 4},
            dict(say, id="again", text="Hello there, how are you?", wav=True, glb=True),
            {"id": "rpm3", "command": "say", "text": "Good morning.", "avatar": str(FIXTURES / "rpm_meshopt.glb"),
             "m": 3, "wav": True, "glb": True},
        ]
        lines = [json.dumps(j) for j in jobs]
        lines.insert(3, "")                   # blank: no job, no result
        lines.insert(5, '{"id": "broken", ')  # not JSON: an error result naming the line
        path = self.dir / "jobs.jsonl"
        path.write_text("\n".join(lines) + "\n")
        return path

    def test_local_cluster_equals_batch(self):
        jobs = self.write_jobs()
        batch = subprocess.run([CLI, "batch", str(jobs), "--out", str(self.dir / "batch")],
                               capture_output=True, text=True)
        env = dict(os.environ, PYTHONPATH=os.environ.get("PYTHONPATH", ""))
        dask = subprocess.run([sys.executable, str(ROOT / "scripts" / "dask-batch.py"), str(jobs),
                               "--out", str(self.dir / "dask"), "--workers", "2", "--chunk", "2"],
                              capture_output=True, text=True, env=env)
        self.assertEqual(dask.returncode, batch.returncode, dask.stderr)
        self.assertNotEqual(batch.returncode, 0)  # the bad jobs fail
        self.assertEqual(dask.stdout, batch.stdout)
        results = [json.loads(line) for line in dask.stdout.splitlines()]
        self.assertEqual([r["status"] for r in results], ["ok", "ok", "ok", "error", "error", "ok", "ok", "ok"])
        self.assertEqual(tree(self.dir / "dask"), tree(self.dir / "batch"))
        self.assertIn("again.glb", tree(self.dir / "dask"))
        # The stamps resume either way: a batch over the Dask run's outputs skips every good job.
        resumed = subprocess.run([CLI, "batch", str(jobs), "--out", str(self.dir / "dask")], capture_output=True,
                                 text=True)
        statuses = [json.loads(line)["status"] for line in resumed.stdout.splitlines()]
        self.assertEqual(statuses, ["skipped", "skipped", "skipped", "error", "error", "skipped", "skipped", "skipped"])


if __name__ == "__main__":
    unittest.main()
