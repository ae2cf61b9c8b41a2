#include "ui/session/SessionSpeech.h"

#include "core/document/Commands.h"

namespace vl::ui {

SessionSpeech::SessionSpeech(SessionCore& core, decltype(SpeechEngines::synthesizer) synthesizer)
    : core_(core), service_(std::move(synthesizer)) {
    core_.onNewDocument([this] { service_.clear(); });
}

void SessionSpeech::setSettings(SpeechSettings speech) {
    const SpeechSettings& current = core_.document().speech;
    if (speech == current) return;
    const bool rateOnly = speech.text == current.text && speech.voice == current.voice;
    const std::string name = rateOnly ? "Speaking rate " + std::to_string(speech.wordsPerMinute) + " wpm"
                             : speech.voice != current.voice ? "Voice " + speech.voice
                                                             : std::string("Say text");
    core_.commit(name, edit::setSpeech(core_.document(), std::move(speech)), rateOnly ? "speech-rate" : "");
}

const SpeechPlayback* SessionSpeech::playback() {
    return service_.playback(core_.document(), core_.inputs());
}

void SessionSpeech::poll() {
    if (auto failed = service_.poll()) core_.messages().error("Say: " + *failed);
}

} // namespace vl::ui
