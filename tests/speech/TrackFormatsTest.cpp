#include "core/speech/TrackFormats.h"

#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/gltf/TargetNames.h"
#include "tests/speech/SpeechTestModels.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace vl;

namespace {

SpeechTrackFile oculusTrack(std::vector<std::string> values) {
    SpeechTrackFile t;
    t.metadata.soundFile = "a.wav";
    t.metadata.duration = 0.1 * static_cast<double>(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        t.mouthCues.push_back({0.1 * static_cast<double>(i), 0.1 * static_cast<double>(i + 1), values[i]});
    return t;
}

std::string errorOf(const SpeechTrackFile& track, TrackFormat format) {
    try {
        formatTrack(track, format, "t.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace

TEST(TrackFormats, EveryOculusVisemeHasARhubarbShapeAndATalkingHeadName) {
    const std::set<char> shapes = {'A', 'B', 'C', 'D', 'E', 'F', 'G', 'H', 'X'};
    std::set<char> used;
    for (const std::string& name : oculusVisemeNames()) {
        const char shape = rhubarbShapeOfOculus(name);
        EXPECT_TRUE(shapes.count(shape)) << name;
        used.insert(shape);
        EXPECT_FALSE(talkingHeadVisemeOfOculus(name).empty());
    }
    EXPECT_EQ(rhubarbShapeOfOculus("sil"), 'X');
    EXPECT_EQ(rhubarbShapeOfOculus("PP"), 'A');
    EXPECT_EQ(rhubarbShapeOfOculus("FF"), 'G');
    EXPECT_EQ(rhubarbShapeOfOculus("aa"), 'D');
    EXPECT_EQ(rhubarbShapeOfOculus("ou"), 'F');
    EXPECT_GE(used.size(), 7u); // closed, teeth, open, wide, rounded, puckered, lip on teeth, rest
    EXPECT_EQ(talkingHeadVisemeOfOculus("ih"), "I");
    EXPECT_EQ(talkingHeadVisemeOfOculus("oh"), "O");
    EXPECT_EQ(talkingHeadVisemeOfOculus("ou"), "U");
    EXPECT_EQ(talkingHeadVisemeOfOculus("kk"), "kk");
}

TEST(TrackFormats, RhubarbIsRhubarbsLayoutWithItsShapesOnly) {
    // Any spelling of the Oculus names, rest, and shapes that are already Rhubarb's.
    const SpeechTrackFile track =
        oculusTrack({"rest", "viseme_PP", "viseme_PP", "PP", "viseme_aa", "I", "viseme_O", "X", "B", "sil"});
    const Json json = parseJsonStrict(formatTrack(track, TrackFormat::Rhubarb, "t.json"), "t.json");
    ASSERT_EQ(json.size(), 2u); // metadata and mouthCues, nothing a strict consumer would trip on
    EXPECT_EQ(json["metadata"]["soundFile"], "a.wav");
    EXPECT_DOUBLE_EQ(json["metadata"]["duration"].get<double>(), 1.0);
    std::vector<std::string> values;
    double end = 0;
    for (const auto& cue : json["mouthCues"]) {
        EXPECT_DOUBLE_EQ(cue["start"].get<double>(), end);
        end = cue["end"].get<double>();
        values.push_back(cue["value"]);
    }
    EXPECT_DOUBLE_EQ(end, 1.0);
    // X, A (three cues joined), D, B (ih), E (oh), X, B, X.
    EXPECT_EQ(values, (std::vector<std::string>{"X", "A", "D", "B", "E", "X", "B", "X"}));
}

TEST(TrackFormats, TalkingHeadHasMillisecondsAndItsNames) {
    const SpeechTrackFile track = oculusTrack({"rest", "viseme_ih", "viseme_PP", "oh"});
    const Json json = parseJsonStrict(formatTrack(track, TrackFormat::TalkingHead, "t.json"), "t.json");
    EXPECT_EQ(json["visemes"], Json::parse(R"(["sil", "I", "PP", "O"])"));
    ASSERT_EQ(json["vtimes"].size(), 4u);
    EXPECT_NEAR(json["vtimes"][1].get<double>(), 100.0, 1e-9);
    EXPECT_NEAR(json["vdurations"][3].get<double>(), 100.0, 1e-9);
}

TEST(TrackFormats, ANameWithoutAShapeIsRefusedNamingTheCue) {
    const SpeechTrackFile track = oculusTrack({"sil", "v3", "aa"});
    EXPECT_NE(errorOf(track, TrackFormat::Rhubarb).find("mouth cue 1: 'v3'"), std::string::npos)
        << errorOf(track, TrackFormat::Rhubarb);
    EXPECT_NE(errorOf(track, TrackFormat::TalkingHead).find("map_rhubarb.csv"), std::string::npos);
    // A Rhubarb shape is not a TalkingHead viseme.
    EXPECT_NE(errorOf(oculusTrack({"A"}), TrackFormat::TalkingHead).find("'A'"), std::string::npos);
    EXPECT_EQ(errorOf(track, TrackFormat::Oculus), "");
}

TEST(TrackPlayback, RoundTripsAndPlaysAsTheFaceTrack) {
    const auto models = test::speechModels(6, {0, 1, 1, 2, 0, 2}, 7);
    const auto phonemes = test::timed(
        {{"sil", 0.05}, {"P3", 0.2}, {"P7", 0.03}, {"P0", 0.04}, {"P11", 0.3}, {"P5", 0.01}, {"sil", 0.2}});
    for (const auto interpolation :
         {runtime::Interpolation::Linear, runtime::Interpolation::Cubic, runtime::Interpolation::Dominance}) {
        const PlaybackSettings settings{interpolation};
        const FaceTrack full(models.full, phonemes, settings, "test");
        const FaceTrack reduced(models.reduced, phonemes, settings, "test");
        SpeechTrackFile track;
        track.mouthCues = full.cues();
        track.playback = TrackPlayback{toString(interpolation), settings.dominanceRate, playbackOf(full),
                                       playbackOf(reduced)};
        const SpeechTrackFile read = parseTrackJson(formatTrackJson(track), "t.json");
        ASSERT_EQ(read.playback, track.playback);
        // The curve rebuilt from the file gives the face's weights at every time, to the bit.
        for (const FaceTrack* face : {&full, &reduced}) {
            const FacePlayback& playback = face == &full ? read.playback->full : read.playback->reduced;
            const runtime::KeyframeCurve curve = curveOf(playback, *read.playback, "t.json");
            ASSERT_EQ(playback.keys.size(), face->keyCount());
            for (double t = -0.1; t < 1.0; t += 0.0037) {
                std::vector<float> weights(face->keyCount(), 0.0f);
                runtime::KeyWeight terms[4];
                const std::size_t count = curve.weightsAt(t, terms);
                for (std::size_t j = 0; j < count; ++j)
                    if (terms[j].key != runtime::kRestKey) weights[terms[j].key] += terms[j].weight;
                EXPECT_EQ(weights, face->keyWeights(t)) << "t = " << t;
            }
        }
        EXPECT_EQ(read.playback->reduced.keys[1].members, (std::vector<std::string>{"v1", "v2"}));
    }
}

TEST(TrackPlayback, BadPlaybackNamesThePath) {
    const auto models = test::speechModels(3, {0, 1, 1}, 3);
    const FaceTrack full(models.full, test::timed({{"P1", 0.2}, {"P4", 0.2}}), PlaybackSettings{}, "test");
    SpeechTrackFile track;
    track.mouthCues = full.cues();
    track.playback = TrackPlayback{"cubic", 25, playbackOf(full), playbackOf(full)};
    std::string text = formatTrackJson(track);
    const auto bad = [&](const std::string& from, const std::string& to, const std::string& phrase) {
        std::string edited = text;
        const auto at = edited.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        edited.replace(at, from.size(), to);
        try {
            parseTrackJson(edited, "t.json");
            FAIL() << "expected an error for " << to;
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos) << e.what();
        }
    };
    bad("\"interpolation\": \"cubic\", \"dominanceRate\"", "\"interpolation\": \"spline\", \"dominanceRate\"",
        "spline");
    bad("\"keyframes\": [[", "\"keyframes\": [[0.1, 9, 1], [", "/playback/full/keyframes/0");
}
