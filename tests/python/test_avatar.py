"""visemelab.reduce_avatar against `visemelab avatar reduce`: the same reduced avatar, byte for byte."""

import json
import unittest

import visemelab
from support import FIXTURES, TempDirTest, run_cli


def without_timings(report):
    report = json.loads(report)
    report.pop("timing_ms", None)
    return report


class ReduceAvatarTest(TempDirTest):
    def reduce_both_ways(self, fixture, cli_options, **api_options):
        source = FIXTURES / fixture
        out, report = self.dir / "cli.glb", self.dir / "cli.json"
        run_cli("avatar", "reduce", source, "--out", out, "--report", report, *cli_options)
        glb, api_report = visemelab.reduce_avatar(source.read_bytes(), name=str(source), output=str(out),
                                                  **api_options)
        self.assertIsInstance(glb, bytes)
        self.assertEqual(glb, out.read_bytes())
        self.assertEqual(without_timings(api_report), without_timings(report.read_text()))
        return glb

    def test_plain_avatar_equals_the_cli(self):
        self.reduce_both_ways("rpm_plain.glb", ["-m", "4"], m=4)

    def test_options_equal_the_cli(self):
        self.reduce_both_ways("rpm_meshopt.glb",
                              ["-m", "5", "--names", "merged", "--pin", "viseme_aa", "--weights", "area"],
                              m=5, names="merged", pin=["viseme_aa"], weights="area")

    def test_vrm_with_targets_and_max_error(self):
        self.reduce_both_ways("vroid_vrm0.glb", ["--targets", "Fcl_MTH_[AIUEO]", "--max-error-mm", "2"],
                              targets="Fcl_MTH_[AIUEO]", max_error_mm=2.0)


class ReduceAvatarErrorsTest(TempDirTest):
    def test_broken_glb_names_the_input(self):
        broken = (FIXTURES / "rpm_plain.glb").read_bytes()[:200]
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.reduce_avatar(broken, m=3, name="hero.glb")
        self.assertTrue(caught.exception.culprit.startswith("hero.glb"), caught.exception.culprit)

    def test_unknown_pin_names_the_viseme(self):
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.reduce_avatar((FIXTURES / "rpm_plain.glb").read_bytes(), m=3, pin=["nosuch"])
        self.assertIn("nosuch", str(caught.exception))

    def test_option_mistakes_are_value_errors(self):
        with self.assertRaises(ValueError):
            visemelab.reduce_avatar(b"", m=3, names="both")


if __name__ == "__main__":
    unittest.main()
