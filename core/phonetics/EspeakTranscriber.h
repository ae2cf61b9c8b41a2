#pragma once
// The espeak-ng implementation of PhonemeTranscriber. This header does not include espeak-ng;
// only EspeakTranscriber.cpp does, and only visemelab_phonetics links the library.
#include "core/phonetics/PhonemeTranscriber.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

// A transcriber for an espeak-ng voice ("en-us", "en-gb", "de", "fr", ...). English voices
// (names starting with "en") give ARPAbet, other voices IPA. Throws InputError naming the voice
// when espeak-ng does not know it. espeak-ng is one global engine: transcribers may coexist
// and be used from several threads, calls are serialised.
std::unique_ptr<PhonemeTranscriber> makeEspeakTranscriber(std::string_view voice = "en-us");

// Names of the installed espeak-ng voices, sorted (for a voice picker).
std::vector<std::string> espeakVoiceNames();

} // namespace vl
