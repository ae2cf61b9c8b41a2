"""visemelab.say against `visemelab say`: the same track file and WAV, byte for byte."""

import unittest

import visemelab
from support import ASSETS, FIXTURES, TempDirTest, run_cli

PROJECT = ASSETS / "sample" / "sample.vlproj"
TEXT = "Five quick wizards judge the boxing match."


class SayTest(TempDirTest):
    def test_project_track_and_wav_equal_the_cli(self):
        track, wav = self.dir / "track.json", self.dir / "speech.wav"
        run_cli("say", TEXT, "--project", PROJECT, "--out", track, "--wav", wav, "--rate", 160)
        said = visemelab.say(TEXT, project=PROJECT, rate=160, track_name=track, wav_name=wav)
        self.assertEqual(said["track"], track.read_text())
        self.assertEqual(said["wav"], wav.read_bytes())
        self.assertIsNone(said["glb"])

    def test_avatar_glb_and_formats_equal_the_cli(self):
        avatar = FIXTURES / "rpm_plain.glb"
        track, wav, glb = self.dir / "t.json", self.dir / "a.wav", self.dir / "a.glb"
        run_cli("say", TEXT, "--avatar", avatar, "-m", 4, "--out", track, "--wav", wav, "--glb", glb,
                "--format", "rhubarb", "--blend", "linear")
        said = visemelab.say(TEXT, avatar=avatar, m=4, format="rhubarb", blend="linear", track_name=track,
                             wav_name=wav, glb=True)
        self.assertEqual(said["track"], track.read_text())
        self.assertEqual(said["wav"], wav.read_bytes())
        self.assertEqual(said["glb"], glb.read_bytes())


class SayErrorsTest(TempDirTest):
    def test_missing_project_is_the_culprit(self):
        missing = self.dir / "nothere.vlproj"
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.say(TEXT, project=missing)
        self.assertIn("nothere.vlproj", caught.exception.culprit)

    def test_unknown_voice_is_named(self):
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.say(TEXT, project=PROJECT, voice="xx-nowhere")
        self.assertIn("xx-nowhere", str(caught.exception))

    def test_text_without_words(self):
        with self.assertRaises(visemelab.InputError) as caught:
            visemelab.say("...", project=PROJECT)
        self.assertEqual(caught.exception.culprit, "text")

    def test_flag_mistakes_are_value_errors(self):
        with self.assertRaises(ValueError):
            visemelab.say(TEXT, project=PROJECT, m=3)


if __name__ == "__main__":
    unittest.main()
