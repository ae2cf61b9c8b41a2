#include "core/speech/SpeechSettings.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cctype>

namespace vl {

void checkSpeechSettings(const SpeechSettings& settings, std::string_view where) {
    const std::string at(where);
    if (settings.text.size() > kMaxSpeechTextBytes)
        throwInputError(at + "/text", "the text has " + std::to_string(settings.text.size()) +
                                          " bytes; at most " + std::to_string(kMaxSpeechTextBytes) +
                                          " are kept in a project (speak longer texts with visemelab say "
                                          "--text-file)");
    if (settings.text.find('\0') != std::string::npos)
        throwInputError(at + "/text", "the text holds a NUL byte");
    const std::string& voice = settings.voice;
    if (voice.empty()) throwInputError(at + "/voice", "no voice named (e.g. en-us)");
    if (voice.size() > kMaxVoiceNameBytes)
        throwInputError(at + "/voice", "a voice name of " + std::to_string(voice.size()) +
                                           " bytes (at most " + std::to_string(kMaxVoiceNameBytes) + ")");
    if (!std::all_of(voice.begin(), voice.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '+';
        }))
        throwInputError(at + "/voice", "'" + voice + "' is not a voice name (letters, digits and -_+ only)");
    if (settings.wordsPerMinute < kMinWordsPerMinute || settings.wordsPerMinute > kMaxWordsPerMinute)
        throwInputError(at + "/wordsPerMinute",
                        "the speaking rate must be " + std::to_string(kMinWordsPerMinute) + " to " +
                            std::to_string(kMaxWordsPerMinute) + " words per minute, not " +
                            std::to_string(settings.wordsPerMinute));
}

} // namespace vl
