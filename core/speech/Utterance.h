#pragma once
// Spoken text as timed phonemes plus its audio: what a speech synthesiser (core/phonetics,
// espeak-ng) produces and what the viseme tracks, the utterance error and the editor consume.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// The phoneme of a pause (at punctuation, or where the synthesiser pauses between words). Not an
// ARPAbet symbol: phoneme tables count it and phoneme -> viseme maps map it to the rest viseme.
inline constexpr std::string_view kSilencePhoneme = "sil";

struct TimedPhoneme {
    std::string phoneme; // ARPAbet (English voices), IPA (others), or kSilencePhoneme
    double start = 0.0;  // seconds from the start of the audio
    double end = 0.0;
    bool operator==(const TimedPhoneme&) const = default;
};

struct Utterance {
    // Contiguous (each starts where the previous ends), from 0 to the end of the audio, every
    // phoneme longer than 0; no two pauses in a row.
    std::vector<TimedPhoneme> phonemes;
    std::vector<std::int16_t> samples; // mono 16-bit PCM
    int sampleRate = 0;                // Hz

    double duration() const { return phonemes.empty() ? 0.0 : phonemes.back().end; }
};

// Throws InputError at `where` (naming the phoneme's index) unless the phonemes are non-empty,
// named, finite, contiguous, start at 0 and each is longer than 0.
void checkTimedPhonemes(std::span<const TimedPhoneme> phonemes, std::string_view where);

} // namespace vl
