#pragma once
// Text -> speech audio with timed phonemes, behind an interface so the rest of VisemeLab never
// sees espeak-ng (EspeakSynthesizer.h makes the espeak-ng one).
#include "core/speech/Utterance.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>

namespace vl {

// Receives audio as it is made, instead of Utterance::samples (to stream a long text to a file).
using AudioSink = std::function<void(std::span<const std::int16_t> samples)>;

class SpeechSynthesizer {
  public:
    virtual ~SpeechSynthesizer() = default;

    // Speaks `text` (UTF-8) and appends to `utterance`: its ARPAbet phonemes with pauses as "sil",
    // timed from the end of what `utterance` already holds (a pause meeting a pause is extended),
    // and its audio to utterance.samples, or to `audio` when given. Text without speech (only
    // punctuation) appends nothing.
    virtual void speak(std::string_view text, Utterance& utterance, const AudioSink& audio = {}) = 0;

    Utterance synthesize(std::string_view text) {
        Utterance utterance;
        speak(text, utterance);
        return utterance;
    }

    virtual int sampleRate() const = 0;

    // Symbols met so far that have no ARPAbet equivalent and were left out, with counts.
    virtual const std::map<std::string, std::size_t>& skippedSymbols() const = 0;
};

} // namespace vl
