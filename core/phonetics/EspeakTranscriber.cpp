#include "core/phonetics/EspeakTranscriber.h"

#include "core/common/Error.h"
#include "core/phonetics/EspeakApi.h"
#include "core/phonetics/EspeakEngine.h"
#include "core/phonetics/EspeakMnemonics.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace vl {

namespace {

// espeak_TextToPhonemes mode bits: bit 1 selects IPA, bits 8-23 the character written between two
// phonemes of a word. A tab cannot be confused with a mnemonic ('_' can: it starts pause names).
constexpr int kIpaBit = 0x02;
constexpr int kSeparator = '\t';

// Whether `text` ends at a clause break (after closing quotes and brackets): espeak pauses there.
bool endsAtPause(std::string_view text) {
    while (!text.empty()) {
        const auto c = static_cast<unsigned char>(text.back());
        if (std::isspace(c) || c == '"' || c == '\'' || c == ')' || c == ']' || c == '}') {
            text.remove_suffix(1);
        } else if (text.ends_with("\u201D") || text.ends_with("\u2019") || text.ends_with("\u00BB")) {
            text.remove_suffix(text.ends_with("\u00BB") ? 2 : 3); // closing ” ’ »
        } else {
            break;
        }
    }
    return !text.empty() && (std::string_view(".,;:!?").find(text.back()) != std::string_view::npos ||
                             text.ends_with("\u2026")); // …
}

class EspeakTranscriber final : public PhonemeTranscriber {
  public:
    explicit EspeakTranscriber(std::string voice) : voice_(std::move(voice)) {
        std::lock_guard lock(espeak::engineMutex());
        espeak::ensureInitialised();
        const std::string language = espeak::selectVoice(voice_);
        notation_ = language.starts_with("en") ? PhonemeNotation::Arpabet : PhonemeNotation::Ipa;
    }

    std::vector<std::string> transcribe(std::string_view text) override {
        std::string input(text);
        std::replace(input.begin(), input.end(), '\0', ' '); // espeak reads up to the first NUL
        std::vector<std::string> phonemes;
        std::lock_guard lock(espeak::engineMutex());
        espeak::selectVoice(voice_);
        const int mode = (notation_ == PhonemeNotation::Ipa ? kIpaBit : 0) | (kSeparator << 8);
        const void* cursor = input.c_str();
        // One clause per call; espeak advances `cursor` and sets it to null after the last one.
        // The returned buffer is reused by the next call, so each clause is parsed right away.
        // Every clause but the last ended at punctuation or a blank line, where speech pauses.
        while (cursor) {
            const char* clause = espeak::api().TextToPhonemes(&cursor, espeakCHARS_UTF8, mode);
            if (clause && *clause) {
                if (notation_ == PhonemeNotation::Arpabet) {
                    appendArpabetForEspeakClause(clause, kSeparator, phonemes, skipped_);
                } else {
                    // IPA output writes every marker as an empty symbol, so pauses inside a
                    // clause cannot be told from glottal onsets: only clause ends count.
                    for (const auto word : splitNonEmpty(clause, ' '))
                        appendIpaForEspeakWord(splitNonEmpty(word, kSeparator), phonemes);
                }
            }
            if (cursor || endsAtPause(input)) appendSilence(phonemes);
        }
        return phonemes;
    }

    PhonemeNotation notation() const override { return notation_; }
    const std::map<std::string, std::size_t>& skippedSymbols() const override { return skipped_; }

  private:
    std::string voice_;
    PhonemeNotation notation_ = PhonemeNotation::Arpabet;
    std::map<std::string, std::size_t> skipped_;
};

} // namespace

std::unique_ptr<PhonemeTranscriber> makeEspeakTranscriber(std::string_view voice) {
    return std::make_unique<EspeakTranscriber>(std::string(voice));
}

std::vector<std::string> espeakVoiceNames() {
    std::lock_guard lock(espeak::engineMutex());
    espeak::ensureInitialised();
    std::set<std::string> names;
    // `languages` is a priority byte followed by the language code.
    for (const espeak_VOICE** voice = espeak::api().ListVoices(nullptr); voice && *voice; ++voice)
        if ((*voice)->languages && (*voice)->languages[1]) names.insert((*voice)->languages + 1);
    return {names.begin(), names.end()};
}

} // namespace vl
