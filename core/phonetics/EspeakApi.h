#pragma once
// espeak-ng's functions, loaded with dlopen the first time speech is needed: programs and commands
// that never transcribe or speak (visemelab reduce, export, ...) never load libespeak-ng and the
// thirty audio libraries it pulls in. Internal to visemelab_phonetics (the Espeak*.cpp files).
#include <espeak-ng/speak_lib.h>

namespace vl::espeak {

struct Api {
    decltype(&espeak_Initialize) Initialize = nullptr;
    decltype(&espeak_SetVoiceByName) SetVoiceByName = nullptr;
    decltype(&espeak_SetVoiceByProperties) SetVoiceByProperties = nullptr;
    decltype(&espeak_GetCurrentVoice) GetCurrentVoice = nullptr;
    decltype(&espeak_ListVoices) ListVoices = nullptr;
    decltype(&espeak_TextToPhonemes) TextToPhonemes = nullptr;
    decltype(&espeak_SetParameter) SetParameter = nullptr;
    decltype(&espeak_SetSynthCallback) SetSynthCallback = nullptr;
    decltype(&espeak_Synth) Synth = nullptr;
};

// With the engine lock held (EspeakEngine.h). Loads the library once; throws std::runtime_error
// naming the library and the Debian package when it or one of its functions is missing.
const Api& api();

} // namespace vl::espeak
