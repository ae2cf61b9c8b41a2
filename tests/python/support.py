"""What the Python package tests share: the paths ctest passes and a CLI runner."""

import os
import pathlib
import subprocess
import tempfile
import unittest

ROOT = pathlib.Path(__file__).resolve().parents[2]
ASSETS = ROOT / "assets"
CLI = os.environ.get("VISEMELAB_CLI", str(ROOT / "build" / "release" / "app" / "visemelab"))
FIXTURES = pathlib.Path(os.environ.get("VISEMELAB_AVATAR_FIXTURES", ROOT / "build" / "release" / "avatar-fixtures"))


def run_cli(*args, check=True):
    """Runs the built `visemelab` and returns the completed process (stdout, stderr as text)."""
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"visemelab {' '.join(map(str, args))} failed ({done.returncode}): {done.stderr}")
    return done


class TempDirTest(unittest.TestCase):
    """A test with its own temporary folder, self.dir."""

    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="visemelab-py-")
        self.dir = pathlib.Path(self._tmp.name)
        # Each test its own speech cache, so the CLI and the API never share an entry by accident.
        os.environ["VISEMELAB_CACHE_DIR"] = str(self.dir / "cache")

    def tearDown(self):
        self._tmp.cleanup()
