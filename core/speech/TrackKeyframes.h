#pragma once
// Keyframes for the runtime's KeyframeAnimation from timed phonemes: the one place that decides
// how speech is played, so the CLI, the glTF animation, the utterance error and the editor all
// show the same motion.
#include "core/common/EnumNames.h"
#include "core/runtime/Animation.h"
#include "core/runtime/PackageFormat.h"
#include "core/speech/Utterance.h"

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace vl {

struct PlaybackSettings {
    runtime::Interpolation interpolation = runtime::Interpolation::Cubic;
    // A phoneme longer than twice this holds its shape: keyframes at start + hold and end - hold;
    // a shorter one has one keyframe at its middle.
    double hold = 0.06;
    double dominanceRate = runtime::kDefaultDominanceRate; // 1/s, for Interpolation::Dominance
};

template <> struct EnumNames<runtime::Interpolation> {
    static constexpr const char* what = "interpolation";
    static constexpr EnumName<runtime::Interpolation> names[] = {
        {runtime::Interpolation::Linear, "linear"},
        {runtime::Interpolation::Cubic, "cubic"},
        {runtime::Interpolation::Dominance, "dominance"}};
};

// The dominance magnitude alpha of a phoneme (Cohen and Massaro): how strongly its mouth shape
// resists its neighbours. Lip closure (P B M) and lip-teeth contact (F V) must be seen, so they
// dominate; HH and the velars take the shape of what is around them. 1 for other phonemes.
float phonemeDominance(std::string_view phoneme);

// One or two keyframes per phoneme (see PlaybackSettings::hold) with its key (kNeutralKey ->
// runtime::kRestKey) and its dominance. `keys` has one entry per phoneme (keysOfPhonemes).
// Times strictly increase when the phonemes are contiguous and longer than 0.
std::vector<runtime::Keyframe> keyframesOf(std::span<const TimedPhoneme> phonemes, std::span<const int> keys,
                                           const PlaybackSettings& settings);

} // namespace vl
