#pragma once
// The espeak-ng implementation of SpeechSynthesizer. This header does not include espeak-ng.
#include "core/phonetics/SpeechSynthesizer.h"

#include <memory>
#include <string>

namespace vl {

struct SpeechVoice {
    std::string voice = "en-us"; // an English espeak-ng voice: en-us, en-gb, en-gb-scotland, en-029, ...
    int wordsPerMinute = 175;    // espeak-ng's speaking rate, kMinWordsPerMinute .. kMaxWordsPerMinute
};

inline constexpr int kMinWordsPerMinute = 80;
inline constexpr int kMaxWordsPerMinute = 450;

// Throws InputError naming the voice when espeak-ng does not know it or it is not English (timed
// phonemes are ARPAbet, named from espeak's English phoneme mnemonics), or naming the rate when it
// is outside the range. Synthesisers share espeak-ng's one engine: calls are serialised.
std::unique_ptr<SpeechSynthesizer> makeEspeakSynthesizer(const SpeechVoice& voice = {});

} // namespace vl
