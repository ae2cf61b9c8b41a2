#pragma once
// The one espeak-ng engine of the process, shared by the transcriber and the synthesiser.
// Internal to visemelab_phonetics; this header does not include espeak-ng.
#include <mutex>
#include <string>

namespace vl::espeak {

// espeak-ng keeps one global engine: every call into it is made with this lock held.
std::mutex& engineMutex();

// With the lock held. Initialises the engine once per process (synchronous output, phoneme
// events on, never exit()) and returns its output sample rate in Hz. Throws std::runtime_error
// when espeak-ng's data files are missing.
int ensureInitialised();

// With the lock held. Selects `voice` (cheap when it is already selected) and returns the
// language code of the selected voice ("en-us"). Throws InputError naming an unknown voice.
std::string selectVoice(const std::string& voice);

// Whether this process has synthesised speech: its engine then holds state a fresh process's has
// not (core/phonetics/EspeakFreshSynthesis.h). Set with the lock held.
bool& hasSpoken();

} // namespace vl::espeak
