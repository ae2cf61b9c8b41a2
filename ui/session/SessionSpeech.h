#pragma once
// The session's speech facet (Say): the document's speech settings as undoable edits, speaking them
// or a typed sequence on a worker thread (SpeechService), and the clip's playback on the full set
// and the current reduction (the document's memoized inputs: DocumentInputs).
#include "core/document/Document.h"
#include "core/phonetics/SpeechEngines.h"
#include "ui/session/SessionCore.h"
#include "ui/session/SpeechService.h"

#include <memory>
#include <string>

namespace vl::ui {

class SessionSpeech {
  public:
    SessionSpeech(SessionCore& core, decltype(SpeechEngines::synthesizer) synthesizer);

    // Text, voice and rate (validated; saved in the project). A rate change while dragging merges
    // into one undo step.
    void setSettings(SpeechSettings speech);
    // Speaks the document's text on a worker thread; poll() makes the speech the current clip.
    void say() { service_.say(core_.document().speech); }
    bool speaking() const { return service_.speaking(); }
    // A typed sequence of phonemes or viseme names, `secondsPerKey` each, becomes the current clip.
    void playSequence(const std::string& sequence, double secondsPerKey) {
        service_.playSequence(core_.document(), sequence, secondsPerKey);
    }
    const std::shared_ptr<const SpeechClip>& clip() const { return service_.clip(); }
    // The current clip on the full set and the current reduction, with its utterance error.
    const SpeechPlayback* playback();

    // For the session: collects a finished synthesis (once per frame); waits for the worker.
    void poll();
    void wait() { service_.wait(); }

  private:
    SessionCore& core_;
    SpeechService service_;
};

} // namespace vl::ui
