#pragma once
// The Say timeline: a time axis, the timed phonemes, the cues of the full and of the reduced set,
// and the per-frame utterance error plotted under them, with a playhead. Clicking or dragging
// anywhere on it scrubs (returns the time under the mouse).
#include "core/speech/Utterance.h"
#include "core/speech/VisemeTrack.h"

#include <imgui.h>

#include <optional>
#include <span>
#include <string>

namespace vl::ui {

struct SpeechTimelineData {
    double duration = 0.0; // seconds
    double time = 0.0;     // the playhead
    std::span<const TimedPhoneme> phonemes;
    std::span<const Cue> fullCues;
    std::span<const Cue> reducedCues; // empty while there is no reduction
    std::string reducedName;          // row label, e.g. "m = 10" (fits the 92 px of row names)
    std::span<const double> error;    // per frame at errorFps; empty = no plot
    double errorFps = 60.0;
    double errorMean = 0.0;
};

// Occupies `size` at the cursor. Returns the time the user clicked or dragged to, if any.
std::optional<double> speechTimeline(const char* id, const SpeechTimelineData& data, ImVec2 size);

} // namespace vl::ui
