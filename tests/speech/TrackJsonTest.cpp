#include "core/speech/TrackJson.h"
#include "core/common/Error.h"
#include "core/io/JsonWrite.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace vl;

namespace {

SpeechTrackFile sampleTrack() {
    SpeechTrackFile t;
    t.metadata = {"audio.wav", 0.7321, "Hi, you.", "", "en-us", 175, "sample.vlproj", "cubic", 30};
    t.mouthCues = {{0.0, 0.1 / 3, "sil"}, {0.1 / 3, 0.5, "aa"}, {0.5, 0.7321, "sil"}};
    t.reducedCues = {{0.0, 0.1 / 3, "sil+PP"}, {0.1 / 3, 0.7321, "aa"}};
    t.phonemes = {{"sil", 0.0, 0.1 / 3}, {"HH", 0.1 / 3, 0.2}, {"AY", 0.2, 0.5}, {"sil", 0.5, 0.7321}};
    t.error = TrackError{1.25e-3, 0.017, 0.4, 0.031, {0.0, 1e-17, 0.017, 2.0 / 3}, {}};
    t.errorCurve = {{1, 102.5, 0.2, 1.5, 0.9}, {2, 20.1, 0.05, 0.9, 0.3}};
    return t;
}

void expectError(std::string_view text, const std::string& phrase) {
    try {
        parseTrackJson(text, "t.json");
        FAIL() << "expected InputError: " << phrase;
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
    }
}

} // namespace

TEST(TrackJson, RoundTripIsExact) {
    const SpeechTrackFile track = sampleTrack();
    const std::string text = formatTrackJson(track);
    EXPECT_EQ(parseTrackJson(text, "t.json"), track);
    EXPECT_EQ(formatTrackJson(parseTrackJson(text, "t.json")), text);
}

TEST(TrackJson, DisplacementErrorRoundTripsAndOlderFilesHaveNone) {
    SpeechTrackFile track = sampleTrack();
    const std::string older = formatTrackJson(track);
    EXPECT_EQ(older.find("displacement"), std::string::npos);
    EXPECT_FALSE(parseTrackJson(older, "t.json").error->displacement);
    track.error->displacement =
        TrackDisplacementError{"mm", 0.42, 1.9, 0.4, {0.0, 0.1 / 3, 0.42, 0.0}, {0.0, 0.2, 1.9, 0.0}};
    const std::string text = formatTrackJson(track);
    EXPECT_NE(text.find("\"displacementUnit\": \"mm\""), std::string::npos) << text;
    EXPECT_EQ(parseTrackJson(text, "t.json"), track);
    expectError(R"({"mouthCues": [{"start": 0, "end": 1, "value": "A"}], "error": {"mean": 0, "max": 0,
                  "displacementUnit": "mm", "displacementRms": -1, "displacementMax": 0}})",
                "/error/displacementRms");
}

// `say --stdin`'s one-line text is written directly; the reference is the pretty text compacted.
TEST(TrackJson, TheLineIsThePrettyTextCompacted) {
    SpeechTrackFile track = sampleTrack();
    track.metadata.text = "Say \"a b\"\n\tand caf\u00e9 \\ {x: [1, 2]}"; // spaces, escapes, UTF-8 in strings
    track.error->displacement =
        TrackDisplacementError{"model units", 0.42, 1.9, 0.4, {0, 1e-5, 2}, {0, 3e20, 2}};
    track.playback = TrackPlayback{"cubic", 12.5, {}, {}};
    for (int i = 0; i < 9; ++i) track.playback->full.keyframes.push_back({0.1 * i, i % 3 - 1, 1.0 / (i + 1)});
    track.playback->full.keys = {{"aa", {"aa"}}, {"PP merged", {"PP", "FF"}}};
    track.playback->reduced = {{{"k0", {}}}, {{0.0, -1, 1.0}}};
    const std::string line = formatTrackJsonLine(track);
    EXPECT_EQ(line, compactJsonText(formatTrackJson(track)));
    EXPECT_EQ(line.find('\n'), std::string::npos);
    EXPECT_EQ(parseTrackJson(line, "line"), track);
    track.errorCurve.clear();
    track.error.reset();
    track.playback.reset();
    EXPECT_EQ(formatTrackJsonLine(track), compactJsonText(formatTrackJson(track)));
}

// The writer keeps each number's text by its bits (numbers repeat in a track): many error frames
// (>= 0), from a pool that repeats and random ones that collide in its table, each read back as
// itself.
TEST(TrackJson, RepeatedAndCollidingNumbersEachReadBackAsThemselves) {
    SpeechTrackFile track = sampleTrack();
    std::mt19937_64 rng(5);
    std::vector<double> pool = {0.0, 1.0, 0.1 / 3, 2.0 / 3, 1e-5, 2.5, 3e20, 60.0, 1e-300};
    for (int i = 0; i < 50; ++i) pool.push_back(std::ldexp(double(rng() >> 11), -int(rng() % 80)));
    std::vector<double>& frames = track.error->frames;
    frames.clear();
    for (int i = 0; i < 20000; ++i)
        frames.push_back(i % 3 ? pool[rng() % pool.size()] : std::ldexp(double(rng() >> 11), -60));
    for (const bool line : {false, true}) {
        const std::string text = line ? formatTrackJsonLine(track) : formatTrackJson(track);
        const SpeechTrackFile back = parseTrackJson(text, "t.json");
        ASSERT_EQ(back.error->frames.size(), frames.size());
        for (std::size_t i = 0; i < frames.size(); ++i) ASSERT_EQ(back.error->frames[i], frames[i]) << i;
        EXPECT_EQ(back, track);
    }
}

TEST(TrackJson, ReadsRhubarbOutput) {
    // The layout Rhubarb Lip Sync 1.x writes with --exportFormat json.
    const auto track = parseTrackJson(R"({
  "metadata": {
    "soundFile": "C:\\speech\\hello.wav",
    "duration": 1.05
  },
  "mouthCues": [
    { "start": 0.00, "end": 0.15, "value": "X" },
    { "start": 0.15, "end": 0.28, "value": "C" },
    { "start": 0.28, "end": 1.05, "value": "X" }
  ]
})",
                                      "hello.json");
    EXPECT_EQ(track.metadata.soundFile, "C:\\speech\\hello.wav");
    EXPECT_EQ(track.metadata.duration, 1.05);
    ASSERT_EQ(track.mouthCues.size(), 3u);
    EXPECT_EQ(track.mouthCues[1], (Cue{0.15, 0.28, "C"}));
    EXPECT_TRUE(track.reducedCues.empty());
    EXPECT_TRUE(track.phonemes.empty());
    EXPECT_FALSE(track.error);
}

TEST(TrackJson, BadTracksNameThePath) {
    expectError("[1]", "t.json:");
    expectError(R"({"metadata": {}})", "mouthCues");
    expectError(
        R"({"mouthCues": [{"start": 0, "end": 1, "value": "A"}, {"start": 2, "end": 3, "value": "B"}]})",
        "t.json:/mouthCues/1: starts at");
    expectError(R"({"mouthCues": [{"start": 0, "end": 1, "value": "A", "extra": 1}]})", "/mouthCues/0");
    expectError(R"({"mouthCues": [{"start": 0, "end": "x", "value": "A"}]})", "/mouthCues/0/end");
    expectError(R"({"mouthCues": [{"start": 0, "end": 1, "value": "A"}], "error": {"mean": -1, "max": 0}})",
                "/error/mean");
    expectError(R"({"mouthCues": [{"start": 0, "end": 1, "value": "A"}],
                    "phonemes": [{"start": 0, "end": 0.5, "value": "AA"}, {"start": 0.4, "end": 1, "value": "B"}]})",
                "phoneme 1");
}
