#include "core/phonetics/EspeakTranscriber.h"

#include "core/common/Error.h"
#include "core/phonetics/EspeakMnemonics.h"

#include <espeak-ng/speak_lib.h>

#include <algorithm>
#include <mutex>
#include <set>
#include <stdexcept>

namespace vl {

namespace {

// espeak_TextToPhonemes mode bits: bit 1 selects IPA, bits 8-23 the character written between two
// phonemes of a word. A tab cannot be confused with a mnemonic ('_' can: it starts pause names).
constexpr int kIpaBit = 0x02;
constexpr int kSeparator = '\t';

// espeak-ng keeps one global engine; every call goes through this lock.
std::mutex& engineMutex() {
    static std::mutex mutex;
    return mutex;
}

// Must be called with the lock held. Initialises the engine once per process.
void ensureInitialised() {
    static bool initialised = false;
    if (initialised) return;
    // DONT_EXIT: without it espeak-ng calls exit() when its data files are missing.
    if (espeak_Initialize(AUDIO_OUTPUT_SYNCHRONOUS, 0, nullptr, espeakINITIALIZE_DONT_EXIT) < 0)
        throw std::runtime_error(
            "espeak-ng could not be initialised (is the espeak-ng-data package installed?)");
    initialised = true;
}

// Must be called with the lock held. Returns the language code of the selected voice ("en-us").
std::string selectVoice(const std::string& voice) {
    static std::string current;
    static std::string currentLanguage;
    if (voice == current) return currentLanguage;
    if (espeak_SetVoiceByName(voice.c_str()) != EE_OK)
        throwInputError("voice '" + voice + "'",
                        "espeak-ng has no such voice (language codes such as en-us, en-gb, de, fr work)");
    const espeak_VOICE* selected = espeak_GetCurrentVoice();
    current = voice;
    currentLanguage = selected && selected->languages ? std::string(selected->languages + 1) : voice;
    return currentLanguage;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || text[i] == separator) {
            if (i > start) parts.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    }
    return parts;
}

class EspeakTranscriber final : public PhonemeTranscriber {
  public:
    explicit EspeakTranscriber(std::string voice) : voice_(std::move(voice)) {
        std::lock_guard lock(engineMutex());
        ensureInitialised();
        const std::string language = selectVoice(voice_);
        notation_ = language.starts_with("en") ? PhonemeNotation::Arpabet : PhonemeNotation::Ipa;
    }

    std::vector<std::string> transcribe(std::string_view text) override {
        std::string input(text);
        std::replace(input.begin(), input.end(), '\0', ' '); // espeak reads up to the first NUL
        std::vector<std::string> phonemes;
        std::lock_guard lock(engineMutex());
        selectVoice(voice_);
        const int mode = (notation_ == PhonemeNotation::Ipa ? kIpaBit : 0) | (kSeparator << 8);
        const void* cursor = input.c_str();
        // One clause per call; espeak advances `cursor` and sets it to null after the last one.
        // The returned buffer is reused by the next call, so each clause is parsed right away.
        while (cursor) {
            const char* clause = espeak_TextToPhonemes(&cursor, espeakCHARS_UTF8, mode);
            if (!clause || !*clause) continue;
            for (const auto word : split(clause, ' ')) {
                const auto symbols = split(word, kSeparator);
                if (notation_ == PhonemeNotation::Arpabet)
                    appendArpabetForEspeakWord(symbols, phonemes, skipped_);
                else
                    appendIpaForEspeakWord(symbols, phonemes);
            }
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
    std::lock_guard lock(engineMutex());
    ensureInitialised();
    std::set<std::string> names;
    // `languages` is a priority byte followed by the language code.
    for (const espeak_VOICE** voice = espeak_ListVoices(nullptr); voice && *voice; ++voice)
        if ((*voice)->languages && (*voice)->languages[1]) names.insert((*voice)->languages + 1);
    return {names.begin(), names.end()};
}

} // namespace vl
