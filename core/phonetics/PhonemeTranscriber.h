#pragma once
// Text -> phoneme sequence, behind an interface so the rest of VisemeLab never sees espeak-ng.
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// Which symbols the phonemes are named with: the 39 ARPAbet phonemes (English voices) or the
// transcriber's own IPA symbols (other languages, where no ARPAbet exists).
enum class PhonemeNotation { Arpabet, Ipa };

class PhonemeTranscriber {
  public:
    virtual ~PhonemeTranscriber() = default;

    // The phonemes of `text` (UTF-8) in reading order, with kSilencePhoneme ("sil",
    // core/speech/Utterance.h) for each pause: at punctuation and blank lines, where the text ends
    // with punctuation, and (English voices) where espeak-ng pauses inside a clause, e.g. before
    // "and" in a long one. Never two pauses in a row, never a pause first.
    virtual std::vector<std::string> transcribe(std::string_view text) = 0;

    virtual PhonemeNotation notation() const = 0;

    // Symbols met so far that have no equivalent in the notation and were left out, with counts
    // (e.g. the Cyrillic letter names an English voice spells out).
    virtual const std::map<std::string, std::size_t>& skippedSymbols() const = 0;
};

} // namespace vl
