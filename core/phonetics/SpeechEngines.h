#pragma once
// The speech engines a front end transcribes and speaks with, injected rather than constructed where
// they are used (the editor's session takes them from the application; tests may pass others).
// Factories, because every worker thread makes its own engine (espeak-ng's state is per process and
// guarded inside the engine).
#include "core/phonetics/EspeakSynthesizer.h"
#include "core/phonetics/PhonemeTranscriber.h"

#include <functional>
#include <memory>
#include <string_view>

namespace vl {

struct SpeechEngines {
    std::function<std::unique_ptr<PhonemeTranscriber>(std::string_view voice)> transcriber;
    std::function<std::unique_ptr<SpeechSynthesizer>(const SpeechVoice& voice)> synthesizer;
};

// espeak-ng for both (makeEspeakTranscriber, makeEspeakSynthesizer).
SpeechEngines espeakSpeechEngines();

} // namespace vl
