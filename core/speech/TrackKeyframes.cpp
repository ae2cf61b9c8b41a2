#include "core/speech/TrackKeyframes.h"

#include "core/speech/VisemeTrack.h"

#include <string>
#include <unordered_map>

namespace vl {

float phonemeDominance(std::string_view phoneme) {
    // Design values (not fitted to data): visible articulations high, hidden ones low.
    static const std::unordered_map<std::string_view, float> alpha = {
        {"P", 4.0f},  {"B", 4.0f},  {"M", 4.0f},                              // lips closed
        {"F", 3.0f},  {"V", 3.0f},                                            // lip on teeth
        {"CH", 2.0f}, {"JH", 2.0f}, {"SH", 2.0f}, {"ZH", 2.0f},               // lips protruded
        {"W", 1.5f},  {"UW", 1.5f}, {"UH", 1.5f}, {"OW", 1.5f}, {"OY", 1.5f}, // rounded
        {"AO", 1.5f}, {"TH", 1.5f}, {"DH", 1.5f},                             // tongue seen
        {"R", 1.2f},  {"ER", 1.2f}, {"T", 0.7f},  {"D", 0.7f},  {"N", 0.7f},
        {"L", 0.7f},  {"S", 0.7f},                              // tongue tip, lips free
        {"Z", 0.7f},  {"Y", 0.7f},  {"AH", 0.8f},               // AH is mostly schwa
        {"K", 0.5f},  {"G", 0.5f},  {"NG", 0.5f}, {"HH", 0.3f}, // back of the mouth
    };
    const auto it = alpha.find(phoneme);
    return it == alpha.end() ? 1.0f : it->second;
}

std::vector<runtime::Keyframe> keyframesOf(std::span<const TimedPhoneme> phonemes, std::span<const int> keys,
                                           const PlaybackSettings& settings) {
    std::vector<runtime::Keyframe> keyframes;
    keyframes.reserve(phonemes.size() * 2);
    for (std::size_t i = 0; i < phonemes.size(); ++i) {
        const TimedPhoneme& p = phonemes[i];
        const std::uint32_t key =
            keys[i] == kNeutralKey ? runtime::kRestKey : static_cast<std::uint32_t>(keys[i]);
        const float dominance = phonemeDominance(p.phoneme);
        // Both conditions: a phoneme a hair longer than 2 x hold (2,646 samples at 22,050 Hz is 0.12 s
        // exactly) can round its two times to equal or reversed ones, which the runtime refuses.
        const double first = p.start + settings.hold, last = p.end - settings.hold;
        if (p.end - p.start > 2 * settings.hold && last > first) {
            keyframes.push_back({first, key, dominance});
            keyframes.push_back({last, key, dominance});
        } else {
            keyframes.push_back({0.5 * (p.start + p.end), key, dominance});
        }
    }
    return keyframes;
}

} // namespace vl
