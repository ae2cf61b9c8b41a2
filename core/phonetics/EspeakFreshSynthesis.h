#pragma once
// espeak-ng speech that is byte-identical to a fresh process's, however many sentences a process
// speaks. espeak-ng keeps state between synthesis calls that nothing in its API resets: the second
// sentence of a process differs from the same sentence spoken first (a few samples of audio and so
// the phoneme times). espeak_ng_Terminate + espeak_Initialize, espeak_SetVoiceByName (same or
// another voice) and a fixed priming sentence before each were all tried and all leave it
// (docs/batch.md). So each sentence is spoken by a process of its own, forked from a helper that has
// initialised espeak-ng and spoken nothing: its state is a fresh `visemelab say`'s.
//
// The helper is forked once, when the FreshSpeech is made (make it before starting threads that use
// espeak-ng in this process); it forks one child per sentence, so sentences are spoken in parallel
// on all cores. It exits when the FreshSpeech is destroyed or this process dies.
#include "core/phonetics/EspeakSynthesizer.h"

#include <cstddef>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <sys/types.h>

namespace vl {

class FreshSpeech {
  public:
    // Throws std::runtime_error when the helper cannot be started or espeak-ng not initialised.
    FreshSpeech();
    ~FreshSpeech();
    FreshSpeech(const FreshSpeech&) = delete;
    FreshSpeech& operator=(const FreshSpeech&) = delete;

    struct Spoken {
        Utterance utterance; // phonemes and samples, as makeEspeakSynthesizer(voice)->speak(text) first
        std::map<std::string, std::size_t> skippedSymbols;
    };
    // Thread-safe. Throws the InputError makeEspeakSynthesizer or speak would (voice, rate), with
    // its message; std::runtime_error when the child process fails.
    Spoken speak(const SpeechVoice& voice, std::string_view text) const;

  private:
    int control_ = -1; // SOCK_SEQPACKET to the helper: one byte and a socket per sentence
    pid_t helper_ = -1;
    mutable std::mutex sending_;
};

} // namespace vl
