#pragma once
// A small viseme set with a phoneme map, its unreduced model and a reduction of it, for the
// speech tests: visemes v0..v(n-1) on a grid, phonemes P0..P(2n-1) two per viseme, sil -> v0.
#include "core/export/RuntimePackageWriter.h"
#include "core/mesh/VisemeSet.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReducedModel.h"
#include "core/reduce/Reduction.h"
#include "core/runtime/Animation.h"
#include "core/speech/FaceTrack.h"
#include "core/speech/Utterance.h"
#include "tests/export/TestModels.h"

#include <random>
#include <stdexcept>
#include <string>

namespace vl::test {

struct SpeechModels {
    VisemeSet set;
    FrequencySource source;
    std::vector<double> frequencies;
    ReducedModel full, reduced;
};

inline SpeechModels speechModels(int visemes, const std::vector<int>& groupOf, unsigned seed,
                                 bool mapSilence = true) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-0.05, 0.05);
    SpeechModels m;
    m.set.neutral = gridMesh(5, 4, false);
    for (int v = 0; v < visemes; ++v) {
        Viseme viseme{"v" + std::to_string(v), {}};
        for (const Vec3& p : m.set.neutral.positions)
            viseme.positions.push_back(p + Vec3(d(rng), d(rng), d(rng)));
        m.set.visemes.push_back(std::move(viseme));
    }
    for (int p = 0; p < 2 * visemes; ++p) {
        const std::string name = "P" + std::to_string(p);
        m.source.phonemes.entries.emplace_back(name, 1.0 + p);
        m.source.map.entries.emplace_back(name, "v" + std::to_string(p / 2));
    }
    if (mapSilence) {
        m.source.phonemes.entries.emplace_back(std::string(kSilencePhoneme), 3.0);
        m.source.map.entries.emplace_back(std::string(kSilencePhoneme), "v0");
    }
    std::vector<std::string> names;
    for (const auto& v : m.set.visemes) names.push_back(v.name);
    m.frequencies = visemeFrequencies(m.source, names);
    m.full = unreducedModel(m.set, m.frequencies, m.source);
    m.reduced = buildReducedModel(m.set, m.frequencies, groupOf, m.source);
    return m;
}

// Contiguous phonemes from (name, duration) pairs.
inline std::vector<TimedPhoneme> timed(const std::vector<std::pair<std::string, double>>& items) {
    std::vector<TimedPhoneme> phonemes;
    double t = 0;
    for (const auto& [name, duration] : items) {
        phonemes.push_back({name, t, t + duration});
        t += duration;
    }
    return phonemes;
}

// `count` phonemes of the speechModels map (P0..P(2 visemes - 1) and sil) with random durations
// in [shortest, longest) seconds, for timed().
inline std::vector<std::pair<std::string, double>>
randomSpeech(int visemes, int count, std::mt19937& rng, double shortest = 0.02, double longest = 0.3) {
    std::uniform_real_distribution<double> duration(shortest, longest);
    std::vector<std::pair<std::string, double>> items;
    for (int i = 0; i < count; ++i) {
        const int p = static_cast<int>(rng() % (2 * visemes + 1));
        items.emplace_back(p == 2 * visemes ? "sil" : "P" + std::to_string(p), duration(rng));
    }
    return items;
}

// A face as a device plays it: the model encoded as a runtime package and the track's keyframes
// played by runtime::KeyframeAnimation.
struct RuntimeFace {
    runtime::Package package;
    runtime::KeyframeAnimation animation;

    explicit RuntimeFace(const FaceTrack& track) {
        const std::string bytes = encodeRuntimePackage(track.model());
        std::string error;
        if (!package.load(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), error) ||
            !animation.setKeyframes(package, track.curve().keyframes(), track.curve().interpolation(), error,
                                    track.curve().dominanceRate()))
            throw std::runtime_error(error);
    }
    RuntimeFace(const RuntimeFace&) = delete; // the animation points to the package
    std::vector<float> positions(double t) const {
        std::vector<float> out(3 * std::size_t(package.vertexCount()));
        animation.evaluate(t, out.data());
        return out;
    }
};

} // namespace vl::test
