#include "core/phonetics/EspeakEngine.h"

#include "core/common/Error.h"

#include "core/phonetics/EspeakApi.h"

#include <stdexcept>

namespace vl::espeak {

std::mutex& engineMutex() {
    static std::mutex mutex;
    return mutex;
}

bool& hasSpoken() {
    static bool spoken = false;
    return spoken;
}

int ensureInitialised() {
    static int sampleRate = 0;
    if (sampleRate > 0) return sampleRate;
    // DONT_EXIT: without it espeak-ng calls exit() when its data files are missing. PHONEME_EVENTS:
    // synthesis reports each phoneme with its sample position (the synthesiser's timing);
    // espeak_TextToPhonemes is unaffected.
    constexpr int kBufferMs = 200; // audio handed to the synthesis callback per call
    sampleRate = espeak::api().Initialize(AUDIO_OUTPUT_SYNCHRONOUS, kBufferMs, nullptr,
                                          espeakINITIALIZE_DONT_EXIT | espeakINITIALIZE_PHONEME_EVENTS);
    if (sampleRate <= 0) {
        sampleRate = 0;
        throw std::runtime_error(
            "espeak-ng could not be initialised (is the espeak-ng-data package installed?)");
    }
    return sampleRate;
}

std::string selectVoice(const std::string& voice) {
    static std::string current;
    static std::string currentLanguage;
    if (voice == current) return currentLanguage;
    // A voice file name ("en-us", "gmw/en") or, failing that, a language code: British English is
    // the voice "en" whose language is "en-gb".
    espeak_VOICE byLanguage{};
    byLanguage.languages = voice.c_str();
    if (espeak::api().SetVoiceByName(voice.c_str()) != EE_OK &&
        espeak::api().SetVoiceByProperties(&byLanguage) != EE_OK)
        throwInputError("voice '" + voice + "'",
                        "espeak-ng has no such voice (language codes such as en-us, en-gb, de, fr work)");
    const espeak_VOICE* selected = espeak::api().GetCurrentVoice();
    current = voice;
    currentLanguage = selected && selected->languages ? std::string(selected->languages + 1) : voice;
    return currentLanguage;
}

} // namespace vl::espeak
