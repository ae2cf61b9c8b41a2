#include "core/speech/VisemeTrack.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace vl {

std::vector<int> keysOfPhonemes(std::span<const TimedPhoneme> phonemes, const ReducedModel& model,
                                std::string_view where) {
    std::unordered_map<std::string_view, int> keyOf;
    for (const auto& [phoneme, key] : model.phonemeToKey) keyOf.emplace(phoneme, key);
    std::vector<int> keys;
    keys.reserve(phonemes.size());
    std::vector<std::string> unmapped;
    for (const TimedPhoneme& p : phonemes) {
        const auto it = keyOf.find(p.phoneme);
        if (it != keyOf.end()) {
            keys.push_back(it->second);
            continue;
        }
        keys.push_back(kNeutralKey);
        if (p.phoneme != kSilencePhoneme &&
            std::find(unmapped.begin(), unmapped.end(), p.phoneme) == unmapped.end())
            unmapped.push_back(p.phoneme);
    }
    if (!unmapped.empty()) {
        std::string list;
        for (const auto& name : unmapped) list += (list.empty() ? "" : ", ") + name;
        throwInputError(where, "the phoneme -> viseme map does not map " + list);
    }
    return keys;
}

std::vector<Cue> cuesOf(std::span<const TimedPhoneme> phonemes, std::span<const int> keys,
                        const ReducedModel& model) {
    std::vector<Cue> cues;
    for (std::size_t i = 0; i < phonemes.size(); ++i) {
        if (i > 0 && keys[i] == keys[i - 1]) {
            cues.back().end = phonemes[i].end;
            continue;
        }
        const std::string value = keys[i] == kNeutralKey ? std::string(kRestCue)
                                                         : model.keys[static_cast<std::size_t>(keys[i])].name;
        cues.push_back({phonemes[i].start, phonemes[i].end, value});
    }
    return cues;
}

void checkCues(std::span<const Cue> cues, std::string_view where) {
    if (cues.empty()) throwInputError(where, "no cues");
    for (std::size_t i = 0; i < cues.size(); ++i) {
        const Cue& c = cues[i];
        const std::string at = std::string(where) + "/" + std::to_string(i);
        if (c.value.empty()) throwInputError(at, "empty value");
        if (!std::isfinite(c.start) || !std::isfinite(c.end)) throwInputError(at, "time is not finite");
        if (i > 0 && c.start != cues[i - 1].end)
            throwInputError(at, "starts at " + std::to_string(c.start) +
                                    " s, not where the previous cue ends (" +
                                    std::to_string(cues[i - 1].end) + " s)");
        if (!(c.end > c.start)) throwInputError(at, "does not last longer than 0 s");
    }
}

} // namespace vl
