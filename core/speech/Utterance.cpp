#include "core/speech/Utterance.h"

#include "core/common/Error.h"

#include <cmath>

namespace vl {

void checkTimedPhonemes(std::span<const TimedPhoneme> phonemes, std::string_view where) {
    if (phonemes.empty()) throwInputError(where, "no phonemes");
    for (std::size_t i = 0; i < phonemes.size(); ++i) {
        const TimedPhoneme& p = phonemes[i];
        const std::string at = std::string(where) + ": phoneme " + std::to_string(i);
        if (p.phoneme.empty()) throwInputError(at, "empty phoneme name");
        if (!std::isfinite(p.start) || !std::isfinite(p.end)) throwInputError(at, "time is not finite");
        const double expectedStart = i == 0 ? 0.0 : phonemes[i - 1].end;
        if (p.start != expectedStart)
            throwInputError(at, "starts at " + std::to_string(p.start) +
                                    " s, not where the previous one ends (" + std::to_string(expectedStart) +
                                    " s)");
        if (!(p.end > p.start)) throwInputError(at, "'" + p.phoneme + "' does not last longer than 0 s");
    }
}

} // namespace vl
