// Writes what the three.js player test (tests/web/player.test.mjs) compares against: for an avatar,
// a speech track (fixed timed phonemes, no espeak-ng) in each blending, with its playback section,
// and the C++ runtime's key weights at sampled times (FaceTrack::keyWeights, the evaluator every
// VisemeLab front end plays speech with).
//   write_player_reference AVATAR.glb OUT_DIR
// OUT_DIR/<blend>.track.json and OUT_DIR/<blend>.weights.json for blend = linear, cubic, dominance.
#include "core/common/AtomicFile.h"
#include "core/common/JsonParse.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GltfDocument.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/speech/FaceTrack.h"
#include "core/speech/TrackFormats.h"
#include "core/speech/TrackPlayback.h"

#include <cstdio>
#include <exception>
#include <filesystem>

namespace {

// "Bob would fix the chair": contiguous ARPAbet with pauses, long and short phonemes.
std::vector<vl::TimedPhoneme> sentence() {
    const std::pair<const char*, double> items[] = {
        {"sil", 0.12}, {"B", 0.07},  {"AA", 0.16}, {"B", 0.06}, {"W", 0.05}, {"UH", 0.04},
        {"D", 0.03},   {"F", 0.09},  {"IH", 0.07}, {"K", 0.05}, {"S", 0.08}, {"DH", 0.03},
        {"AH", 0.04},  {"CH", 0.09}, {"EH", 0.11}, {"R", 0.1},  {"sil", 0.2}};
    std::vector<vl::TimedPhoneme> phonemes;
    double t = 0;
    for (const auto& [name, duration] : items) {
        phonemes.push_back({name, t, t + duration});
        t += duration;
    }
    return phonemes;
}

vl::Json weightsJson(const vl::FaceTrack& face, const std::vector<double>& times) {
    vl::Json rows = vl::Json::array();
    for (const double t : times) rows.push_back(face.keyWeights(t));
    return rows;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s AVATAR.glb OUT_DIR\n", argv[0]);
        return 2;
    }
    try {
        const std::filesystem::path out = argv[2];
        std::filesystem::create_directories(out);
        const vl::GltfDocument doc = vl::parseGltfDocument(vl::readFileToString(argv[1]), argv[1], {});
        const vl::AvatarScan scan = vl::scanAvatar(doc, {});
        const vl::FrequencySource frequencies =
            vl::defaultAvatarFrequencies(scan, vl::bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus"));
        vl::ReduceSettings settings;
        settings.target = 4;
        const vl::AvatarReduction reduction = vl::reduceAvatar(doc, scan, frequencies, settings, {});
        const vl::ReducedModel full =
            vl::unreducedModel(scan.set, reduction.outcome.frequencies, frequencies);
        const auto phonemes = sentence();
        std::vector<double> times;
        for (double t = -0.05; t < phonemes.back().end + 0.05; t += 0.0133) times.push_back(t);
        for (const auto interpolation :
             {vl::runtime::Interpolation::Linear, vl::runtime::Interpolation::Cubic,
              vl::runtime::Interpolation::Dominance}) {
            const vl::PlaybackSettings playback{interpolation};
            const vl::FaceTrack fullTrack(full, phonemes, playback, argv[1]);
            const vl::FaceTrack reducedTrack(reduction.outcome.model, phonemes, playback, argv[1]);
            vl::SpeechTrackFile track;
            track.metadata.duration = phonemes.back().end;
            track.metadata.interpolation = vl::toString(interpolation);
            track.mouthCues = fullTrack.cues();
            track.reducedCues = reducedTrack.cues();
            track.phonemes = phonemes;
            track.playback = vl::TrackPlayback{vl::toString(interpolation), playback.dominanceRate,
                                               vl::playbackOf(fullTrack), vl::playbackOf(reducedTrack)};
            const std::string stem = vl::toString(interpolation);
            vl::writeFileAtomically(out / (stem + ".track.json"), vl::formatTrackJson(track));
            const vl::Json weights = {{"times", times},
                                      {"full", weightsJson(fullTrack, times)},
                                      {"reduced", weightsJson(reducedTrack, times)}};
            vl::writeFileAtomically(out / (stem + ".weights.json"), weights.dump());
        }
        vl::writeFileAtomically(out / "reduced.glb", reduction.glb);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "write_player_reference: %s\n", e.what());
        return 1;
    }
}
