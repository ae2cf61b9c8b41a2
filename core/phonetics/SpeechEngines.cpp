#include "core/phonetics/SpeechEngines.h"

#include "core/phonetics/EspeakTranscriber.h"

namespace vl {

SpeechEngines espeakSpeechEngines() {
    return {[](std::string_view voice) { return makeEspeakTranscriber(voice); },
            [](const SpeechVoice& voice) { return makeEspeakSynthesizer(voice); }};
}

} // namespace vl
