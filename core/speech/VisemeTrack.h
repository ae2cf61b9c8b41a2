#pragma once
// Timed phonemes -> the keys of a face (the project's visemes, or the merged keys of a reduction)
// -> cues: contiguous runs of one key, the layout Rhubarb Lip Sync writes ("mouthCues").
#include "core/reduce/ReducedModel.h"
#include "core/speech/Utterance.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct Cue {
    double start = 0.0; // seconds
    double end = 0.0;
    std::string value; // key (viseme) name, or kRestCue
    bool operator==(const Cue&) const = default;
};

// The value of a cue showing the neutral face: a pause when the map does not map sil.
inline constexpr std::string_view kRestCue = "rest";
// The key index of the neutral face in keysOfPhonemes.
inline constexpr int kNeutralKey = -1;

// Each phoneme's key in `model` through its phoneme -> key map; a pause the map does not map is
// the neutral face (kNeutralKey). Throws InputError at `where` listing every other phoneme the map
// does not map (e.g. a map without the phonemes of the voice).
std::vector<int> keysOfPhonemes(std::span<const TimedPhoneme> phonemes, const ReducedModel& model,
                                std::string_view where);

// Merged runs of consecutive phonemes with the same key: contiguous, covering the phonemes' time.
std::vector<Cue> cuesOf(std::span<const TimedPhoneme> phonemes, std::span<const int> keys,
                        const ReducedModel& model);

// Throws InputError at `where` (naming the cue's index) unless the cues are non-empty, named,
// finite, each longer than 0 and each starting where the previous ends.
void checkCues(std::span<const Cue> cues, std::string_view where);

} // namespace vl
