"""visemelab.reduce_visemes / load_visemes against `visemelab reduce` on the bundled sample."""

import json
import unittest

import numpy as np

import visemelab
from support import ASSETS, TempDirTest, run_cli

SAMPLE = ASSETS / "sample"


class ReduceVisemesTest(TempDirTest):
    def test_files_and_arrays_reduce_as_the_cli(self):
        report = self.dir / "report.json"
        run_cli("reduce", "--visemes", SAMPLE, "-m", 5, "--weights", "area", "--out", self.dir / "out",
                "--report", report)
        expected = json.loads(report.read_text())

        loaded = visemelab.load_visemes(folder=SAMPLE)
        from_files = visemelab.reduce_visemes(loaded, m=5, weights="area")
        # The same set rebuilt from arrays reduces identically.
        rebuilt = visemelab.VisemeSet(loaded.neutral, loaded.triangles, loaded.visemes)
        from_arrays = visemelab.reduce_visemes(rebuilt, m=5, weights="area")

        for result in (from_files, from_arrays):
            self.assertEqual(len(result["keys"]), 5)
            self.assertEqual(len(result["cost_curve"]), 5)
            self.assertAlmostEqual(result["cost"], result["cost_curve"][-1])
            self.assertEqual(result["groups"], expected["groups"])
            self.assertEqual(result["resting"], expected["rest"]["resting"])
            np.testing.assert_allclose(result["cost_curve"], expected["cost_curve"], rtol=1e-12)
            self.assertEqual(result["optimal"], expected["optimal"])
        self.assertEqual(from_files["groups"], from_arrays["groups"])
        # Costs only fall as keys are added.
        self.assertTrue(all(a >= b for a, b in zip(from_files["cost_curve"], from_files["cost_curve"][1:])))

    def test_merged_key_is_the_frequency_weighted_mean(self):
        s = visemelab.load_visemes(folder=SAMPLE)
        freqs = {name: float(i + 1) for i, name in enumerate(s.names)}
        result = visemelab.reduce_visemes(s, m=3, frequencies=freqs, rest="key")
        for key in result["keys"]:
            members = key["members"]
            total = sum(freqs[m] for m in members)
            mean = sum(freqs[m] * s.visemes[m] for m in members) / total
            np.testing.assert_allclose(key["positions"], mean, rtol=0, atol=1e-9)

    def test_constraints_hold(self):
        s = visemelab.load_visemes(folder=SAMPLE)
        result = visemelab.reduce_visemes(s, m=4, pin=["PP"], apart=[("aa", "oh")], together=[("FF", "TH")])
        groups = result["groups"]
        self.assertIn(["PP"], groups)
        self.assertFalse(any("aa" in g and "oh" in g for g in groups))
        self.assertTrue(any("FF" in g and "TH" in g for g in groups))


class ReduceErrorsTest(TempDirTest):
    def test_bad_triangle_names_the_row(self):
        neutral = np.zeros((3, 3))
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.VisemeSet(neutral, [[0, 1, 7]], {"a": neutral, "b": neutral})
        self.assertEqual(caught.exception.culprit, "triangles[0]")
        self.assertIsInstance(caught.exception, ValueError)

    def test_unknown_viseme_in_a_constraint_is_named(self):
        s = visemelab.load_visemes(folder=SAMPLE)
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.reduce_visemes(s, m=3, pin=["nosuch"])
        self.assertIn("nosuch", str(caught.exception))
        self.assertEqual(caught.exception.culprit, "pin/apart/together")

    def test_missing_file_is_the_culprit(self):
        missing = self.dir / "missing.obj"
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.load_visemes(neutral=SAMPLE / "neutral.obj", files={"a": missing, "b": SAMPLE / "aa.obj"})
        self.assertIn(str(missing), caught.exception.culprit)

    def test_bad_frequency_file_names_file_and_line(self):
        table = self.dir / "freq.csv"
        table.write_text("viseme,frequency\naa,1\noh,-2\n")
        s = visemelab.load_visemes(folder=SAMPLE)
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.reduce_visemes(s, m=3, frequencies=table)
        self.assertTrue(caught.exception.culprit.startswith(str(table)), caught.exception.culprit)


if __name__ == "__main__":
    unittest.main()
