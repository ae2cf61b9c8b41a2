#include "tests/cli/CliRunner.h"

#include "core/common/AtomicFile.h"
#include "core/speech/TrackJson.h"
#include "core/speech/WavFile.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <unistd.h>

using namespace vl;

namespace {

std::string quotedPath(const std::filesystem::path& path) {
    return "'" + path.string() + "'";
}

std::string sampleProject() {
    return quotedPath(std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj");
}

class SayCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = std::filesystem::temp_directory_path() /
              ("visemelab-say-" + std::to_string(::getpid()) + "-" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::filesystem::path dir;
};

} // namespace

TEST_F(SayCli, WritesTrackAudioAndAnimation) {
    const auto out = dir / "track.json", wav = dir / "audio.wav", glb = dir / "anim.glb";
    const auto result =
        test::runCli("say 'Hello, world. How are you?' --project " + sampleProject() + " --out " +
                     quotedPath(out) + " --wav " + quotedPath(wav) + " --glb " + quotedPath(glb));
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("utterance error (m = 10"), std::string::npos) << result.output;
    const SpeechTrackFile track = loadTrackJson(out);
    const WavAudio audio = readWav(wav);
    EXPECT_DOUBLE_EQ(track.metadata.duration, double(audio.samples.size()) / audio.sampleRate);
    EXPECT_EQ(track.metadata.soundFile, "audio.wav");
    EXPECT_EQ(track.mouthCues.back().end, track.metadata.duration);
    EXPECT_EQ(track.reducedCues.back().end, track.metadata.duration);
    EXPECT_EQ(track.phonemes.back().end, track.metadata.duration);
    ASSERT_TRUE(track.error);
    EXPECT_GT(track.error->mean, 0.0);
    EXPECT_EQ(track.error->frames.size(),
              static_cast<std::size_t>(std::ceil(track.metadata.duration * 60)) + 1);
    EXPECT_TRUE(track.errorCurve.empty());
    EXPECT_GT(std::filesystem::file_size(glb), 1000u);
    // Pauses at the comma and the full stop show the rest viseme.
    int rests = 0;
    for (const auto& cue : track.mouthCues) rests += cue.value == "sil";
    EXPECT_GE(rests, 3);
}

TEST_F(SayCli, CorpusFileGivesTheErrorCurve) {
    const auto corpus = dir / "corpus.txt";
    writeFileAtomically(corpus, "The judge measures the house.\nFour poor fire fighters came at noon!\n");
    const auto out = dir / "track.json";
    const auto result =
        test::runCli("say --text-file " + quotedPath(corpus) + " --project " + sampleProject() + " --out " +
                     quotedPath(out) + " --blend dominance --fps 30");
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const SpeechTrackFile track = loadTrackJson(out);
    ASSERT_EQ(track.errorCurve.size(), 14u); // m = 1..n - 1: the sample's sil rests (the rest is free)
    EXPECT_EQ(track.errorCurve.back().mean, 0.0);
    EXPECT_GT(track.errorCurve.front().mean, track.errorCurve[9].mean);
    EXPECT_EQ(track.metadata.interpolation, "dominance");
    EXPECT_EQ(track.metadata.source, corpus.string());
}

TEST_F(SayCli, UsageAndDataErrorsGetTheirExitCodes) {
    const auto out = quotedPath(dir / "t.json");
    const std::string project = " --project " + sampleProject();
    EXPECT_EQ(test::runCli("say" + project + " --out " + out).exitCode, 2);
    EXPECT_EQ(test::runCli("say hi --text-file x.txt" + project + " --out " + out).exitCode, 2);
    EXPECT_EQ(test::runCli("say hi --fps 0" + project + " --out " + out).exitCode, 2);
    EXPECT_EQ(test::runCli("say hi --blend spline" + project + " --out " + out).exitCode, 2);
    auto result = test::runCli("say hi" + project + " --out " + sampleProject());
    EXPECT_EQ(result.exitCode, 2) << result.output;
    EXPECT_NE(result.output.find("would overwrite the input --project"), std::string::npos) << result.output;
    EXPECT_EQ(test::runCli("say hi" + project + " --out " + out + " --wav " + out).exitCode, 2);

    result = test::runCli("say hi --voice xx-none" + project + " --out " + out);
    EXPECT_EQ(result.exitCode, 3) << result.output;
    EXPECT_NE(result.output.find("xx-none"), std::string::npos);
    EXPECT_EQ(test::runCli("say hi --voice de" + project + " --out " + out).exitCode, 3);
    EXPECT_EQ(test::runCli("say hi --rate 5" + project + " --out " + out).exitCode, 3);
    EXPECT_EQ(test::runCli("say ' ... ,,, '" + project + " --out " + out).exitCode, 3);
    EXPECT_EQ(test::runCli("say hi --project " + quotedPath(dir / "none.vlproj") + " --out " + out).exitCode,
              3);
    const auto binary = dir / "blob.txt";
    writeFileAtomically(binary, std::string("\x7F"
                                            "ELF\0\0\0\0",
                                            8));
    result = test::runCli("say --text-file " + quotedPath(binary) + project + " --out " + out);
    EXPECT_EQ(result.exitCode, 3) << result.output;
    EXPECT_NE(result.output.find("blob.txt: binary file"), std::string::npos) << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "t.json"));
}

// espeak-ng (and the audio libraries it pulls in) is loaded on first use only: commands that never
// speak do not load it. glibc's loader lists every library it opens under LD_DEBUG=files.
TEST_F(SayCli, OnlySpeechLoadsEspeak) {
    ::setenv("LD_DEBUG", "files", 1);
    const auto exported =
        test::runCli("export " + sampleProject() + " --format glb --out " + quotedPath(dir / "a.glb"));
    const auto said =
        test::runCli("say hi --project " + sampleProject() + " --out " + quotedPath(dir / "t.json"));
    ::unsetenv("LD_DEBUG");
    ASSERT_EQ(exported.exitCode, 0) << exported.output;
    ASSERT_EQ(said.exitCode, 0) << said.output;
    EXPECT_EQ(exported.output.find("libespeak-ng"), std::string::npos);
    EXPECT_NE(said.output.find("libespeak-ng"), std::string::npos);
}
