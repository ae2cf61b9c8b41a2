#pragma once
// The speech clip on the faces: its clock (the audio's while it plays, else the frames), whether the
// views show it, and typed sequences. Shared by the Reduction panel's Say section, the Visemes
// panel's "Play all" and the views; the clip itself is the session's (SpeechService).
#include "ui/audio/AudioPlayer.h"
#include "ui/session/EditorSession.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

class SpeechPlayer {
  public:
    explicit SpeechPlayer(EditorSession& session) : session_(session) {}

    // Once per frame: adopts a new clip (from its start or where say()/playSequence() said), runs the clock.
    void advance();
    // Says the document's speech text and, once spoken, shows it at `time` seconds, paused when `pause`.
    void say(double time = 0.0, bool pause = false);
    // Plays `sequence` (phonemes or viseme names; empty: every viseme) from `time` seconds.
    void playSequence(std::string sequence, double time = 0.0);
    void play(double from);
    void pause();
    void hide(); // pauses, and the views compare visemes again
    // A new document: nothing playing or shown (a Say or sequence asked for since still starts
    // where it was asked to).
    void reset();
    bool playing() const { return playing_; }
    double time() const { return time_; }
    bool shown() const { return shown_ && session_.speech().clip() != nullptr; }
    // Key weights of the full (visemes) or reduced (groups) face at the playhead; empty when none.
    std::vector<float> weights(bool reduced) const;
    // Phonemes, both cue rows and the error plot under the views; scrubbing moves the playhead.
    void timeline(ImVec2 size);
    const AudioPlayer& audio() const { return audio_; }
    // What the Say tests check: the clip, the playhead, the cues and the error there.
    nlohmann::json probe() const;

    std::string sequence;        // typed sequence: phonemes or viseme names
    float secondsPerKey = 0.18f; // of typed sequences

  private:
    EditorSession& session_;
    double time_ = 0.0;             // seconds into the clip
    bool playing_ = false;          // the clock runs (audio or frame time)
    bool shown_ = false;            // the views show the clip, not the compared viseme
    std::uint64_t clip_ = 0;        // id of the clip this state belongs to
    std::optional<double> startAt_; // a new clip starts here
    bool startPaused_ = false;
    std::shared_ptr<const std::vector<std::int16_t>> samples_; // the clip's samples for the player
    AudioPlayer audio_;
};

} // namespace vl::ui
