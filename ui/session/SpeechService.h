#pragma once
// What the Say section plays: a clip (speech synthesised from the document's speech settings with
// espeak-ng on a worker thread, or a typed sequence of visemes), and derived from the clip and the
// document, two face tracks (the full viseme set and the current reduction) evaluated through the
// runtime's keyframe evaluator (core/speech/FaceTrack.h) and the utterance error between them. The
// tracks are rebuilt when the clip, the reduction inputs or the grouping change.
#include "core/document/Document.h"
#include "core/document/DocumentInputs.h"
#include "core/phonetics/SpeechEngines.h"
#include "core/speech/DisplacementError.h"
#include "core/speech/FaceTrack.h"
#include "core/speech/SpeechSettings.h"
#include "core/speech/UtteranceError.h"
#include "ui/session/BackgroundTask.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

struct SpeechClip {
    std::vector<TimedPhoneme> phonemes; // a typed sequence: its tokens (phonemes or viseme names)
    std::vector<std::int16_t> samples;  // mono 16-bit speech; empty for a typed sequence
    int sampleRate = 0;
    // A typed sequence: the viseme each "phoneme" shows (empty for speech, whose phonemes go
    // through the document's phoneme -> viseme map).
    std::vector<std::string> visemes;
    std::string sequence; // the typed sequence as typed ("" = every viseme, or speech)
    bool loops = false;   // a typed sequence repeats; speech plays once
    std::string label;    // what the views call it
    std::uint64_t id = 0; // new for every clip
    double duration() const { return phonemes.empty() ? 0.0 : phonemes.back().end; }
};

// The clip on the document's faces.
struct SpeechPlayback {
    std::shared_ptr<const SpeechClip> clip;
    std::optional<FaceTrack> full;    // every viseme a key (the viseme mesh's morph targets)
    std::optional<FaceTrack> reduced; // the grouping's keys (the merged mesh's targets), when reduced
    std::optional<UtteranceError> error;
    std::optional<DisplacementError> displacement; // the same error in mm (avatars) or model units
    int groups = 0;                                // m of `reduced`
    std::string problem; // why there are no tracks (e.g. a phoneme the map lacks), or ""
};

// Frames per second of the per-frame error the timeline plots.
inline constexpr double kSpeechErrorFps = 60.0;

class SpeechService {
  public:
    explicit SpeechService(std::function<std::unique_ptr<SpeechSynthesizer>(const SpeechVoice&)> synthesizer)
        : synthesizer_(std::move(synthesizer)) {}
    ~SpeechService() { task_.cancel(); }

    // Speaks `settings` on a worker thread (a running synthesis is cancelled). Throws InputError
    // when there is no text.
    void say(const SpeechSettings& settings);
    bool speaking() const { return task_.running(); }
    // Collects a finished synthesis (the new clip); returns the error message of a failed one.
    std::optional<std::string> poll();
    void wait() { task_.wait(); }

    // A typed sequence: phonemes (through the document's map) or viseme names separated by spaces,
    // each shown for `secondsPerKey`; empty = every viseme in order. Throws InputError naming a
    // token that is neither, or without a viseme set.
    void playSequence(const Document& document, const std::string& sequence, double secondsPerKey);

    const std::shared_ptr<const SpeechClip>& clip() const { return clip_; }
    // No clip and no synthesis running (a new document: the old sentence is not its own).
    void clear();

    // The clip's tracks on the document's full and reduced models (`inputs`: the current grouping,
    // the models, the weights); the tracks are kept while the clip, the reduction inputs, the curve
    // and the target are. Null without a clip.
    const SpeechPlayback* playback(const Document& document, const DocumentInputs& inputs);

  private:
    std::function<std::unique_ptr<SpeechSynthesizer>(const SpeechVoice&)> synthesizer_;
    BackgroundTask<SpeechClip> task_;
    std::shared_ptr<const SpeechClip> clip_;
    std::uint64_t nextId_ = 1;
    // playback() cache and what it was built for (revisions, never addresses).
    SpeechPlayback playback_;
    std::uint64_t builtClip_ = 0, builtRevision_ = 0, builtCurve_ = 0; // 0: nothing built
    bool builtGrouping_ = false;
    int builtTarget_ = 0;
};

} // namespace vl::ui
