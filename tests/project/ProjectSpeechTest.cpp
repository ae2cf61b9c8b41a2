#include "core/project/ProjectSpeech.h"
#include "core/common/Error.h"
#include "core/phonetics/EspeakSynthesizer.h"
#include "core/project/Project.h"
#include "core/speech/VisemeTrack.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace vl;

namespace {

std::filesystem::path sampleProject() {
    return std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "sample.vlproj";
}

// The cue covering time t.
const Cue& cueAt(const std::vector<Cue>& cues, double t) {
    return *std::find_if(cues.begin(), cues.end(), [&](const Cue& c) { return c.start <= t && t < c.end; });
}

} // namespace

TEST(ProjectSpeech, SampleSentenceGivesContiguousTracksWithSilenceAtPauses) {
    const Project project = loadProject(sampleProject());
    const SpeechFaces faces = projectSpeechFaces(project);
    EXPECT_EQ(faces.full.keys.size(), 15u);
    EXPECT_EQ(static_cast<int>(faces.reduced.keys.size()), project.reduction.target);
    const Utterance u = makeEspeakSynthesizer()->synthesize("Hello, world. How are you?");
    const FaceTrack full(faces.full, u.phonemes, {}, "full"),
        reduced(faces.reduced, u.phonemes, {}, "reduced");
    for (const auto* cues : {&full.cues(), &reduced.cues()}) {
        EXPECT_NO_THROW(checkCues(*cues, "cues"));
        EXPECT_EQ(cues->front().start, 0.0);
        EXPECT_EQ(cues->back().end, u.duration());
    }
    // Every pause of the utterance shows the rest viseme in the full track; the sample runs the
    // default model (the rest free), so sil rests in the reduced one: the neutral face, cue "rest".
    int silenceKey = 0;
    for (const auto& [phoneme, key] : faces.reduced.phonemeToKey)
        if (phoneme == kSilencePhoneme) silenceKey = key;
    EXPECT_EQ(silenceKey, kRestingKey);
    int pauses = 0;
    for (const TimedPhoneme& p : u.phonemes) {
        if (p.phoneme != kSilencePhoneme) continue;
        ++pauses;
        const double middle = 0.5 * (p.start + p.end);
        EXPECT_EQ(cueAt(full.cues(), middle).value, "sil");
        EXPECT_EQ(cueAt(reduced.cues(), middle).value, kRestCue);
    }
    EXPECT_GE(pauses, 3); // start, comma, full stop
    const UtteranceError error = measureUtteranceError(full, reduced, faces.weights, 60.0);
    EXPECT_GT(error.mean, 0.0);
    EXPECT_LT(error.relative, 0.5);
}

TEST(ProjectSpeech, ErrorCurveFallsToZeroAtTheFullSet) {
    const Project project = loadProject(sampleProject());
    const Utterance u =
        makeEspeakSynthesizer()->synthesize("The judge measures the house, four poor fire fighters.");
    const auto curve = projectErrorCurve(project, u.phonemes, {}, 30.0);
    // m = 1..14: the rest is free, so sil rests and is never a key; at 14 keys nothing else merges.
    ASSERT_EQ(curve.size(), 14u);
    EXPECT_EQ(curve.front().m, 1);
    EXPECT_EQ(curve.back().error.mean, 0.0);
    EXPECT_GT(curve.front().error.mean, curve[9].error.mean);
    for (std::size_t p = 1; p < curve.size(); ++p) EXPECT_LE(curve[p].cost, curve[p - 1].cost);
}

TEST(ProjectSpeech, PerVisemeFrequenciesAreRefusedWithAReason) {
    Project project = loadProject(sampleProject());
    project.frequencies.phonemes.entries.clear();
    project.frequencies.map.entries.clear();
    for (const auto& v : project.visemes)
        project.frequencies.visemeFrequencies.entries.emplace_back(v.name, 1.0);
    try {
        projectSpeechFaces(project);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("phoneme -> viseme map"), std::string::npos) << e.what();
    }
    // With a map given, it speaks; a map naming visemes the project lacks is refused, naming them.
    const auto assets = std::filesystem::path(VISEMELAB_ASSETS_DIR) / "phonemes";
    const PhonemeVisemeMap oculus = loadPhonemeMapFile(assets / "map_oculus.csv");
    const SpeechFaces faces = projectSpeechFaces(project, &oculus);
    const Utterance u = makeEspeakSynthesizer()->synthesize("Bob, if you please.");
    const FaceTrack full(faces.full, u.phonemes, {}, "full");
    EXPECT_EQ(full.cues().front().value, "sil");
    EXPECT_NE(
        std::find_if(full.cues().begin(), full.cues().end(), [](const Cue& c) { return c.value == "PP"; }),
        full.cues().end());
    // Rhubarb's shapes are read by meaning on these Oculus names (A: closed lips -> PP).
    const PhonemeVisemeMap rhubarb = loadPhonemeMapFile(assets / "map_rhubarb.csv");
    const SpeechFaces rhubarbFaces = projectSpeechFaces(project, &rhubarb);
    const FaceTrack spoken(rhubarbFaces.full, u.phonemes, {}, "rhubarb");
    EXPECT_NE(std::find_if(spoken.cues().begin(), spoken.cues().end(),
                           [](const Cue& c) { return c.value == "PP"; }),
              spoken.cues().end());
    PhonemeVisemeMap unknown;
    unknown.entries = {{"sil", "X"}, {"AA", "jawOpen"}, {"M", "sil"}};
    try {
        projectSpeechFaces(project, &unknown);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("does not have: 'X', 'jawOpen'"), std::string::npos) << e.what();
    }
}
