#pragma once
// Speech tracks on disk: JSON in Rhubarb Lip Sync's layout ({"metadata": {"soundFile", "duration"},
// "mouthCues": [{"start", "end", "value"}]}) for the full viseme set, plus VisemeLab's
// "reducedCues" (the reduction's keys), "phonemes" (timed ARPAbet, same element layout),
// "error" (the utterance error), "errorCurve" (m = 1..n) and "playback" (both faces' keys and
// runtime keyframes: what a player needs to play the track as VisemeLab does). docs/speech.md describes every
// field. Rhubarb's own output files read as tracks with cues only.
#include "core/speech/TrackPlayback.h"
#include "core/speech/Utterance.h"
#include "core/speech/VisemeTrack.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct TrackMetadata {
    std::string soundFile; // the WAV written beside the track, "" when none
    double duration = 0;   // seconds
    std::string text;      // what was said (empty for a corpus file: see source)
    std::string source;    // the text file of a corpus, "" for text given inline
    std::string voice;
    int wordsPerMinute = 0;
    std::string project;
    std::string interpolation; // "linear", "cubic", "dominance"
    double fps = 0;            // of error.frames
    bool operator==(const TrackMetadata&) const = default;
};

// The error as vertex displacement (core/speech/DisplacementError.h): RMS and max over the mouth
// in `unit` ("mm" for avatars, "model units" for mesh files).
struct TrackDisplacementError {
    std::string unit;
    double rms = 0, max = 0, maxTime = 0;
    std::vector<double> rmsFrames, maxFrames; // per frame at metadata.fps
    bool operator==(const TrackDisplacementError&) const = default;
};

struct TrackError {
    double mean = 0, max = 0, maxTime = 0, relative = 0;
    std::vector<double> frames; // per frame at metadata.fps

    // The "displacement*" fields, when written (optional when reading).
    std::optional<TrackDisplacementError> displacement;
    bool operator==(const TrackError&) const = default;
};

struct TrackErrorCurvePoint {
    int m = 0;
    double cost = 0, mean = 0, max = 0, relative = 0;
    bool operator==(const TrackErrorCurvePoint&) const = default;
};

struct SpeechTrackFile {
    TrackMetadata metadata;
    std::vector<Cue> mouthCues;         // full set (or Rhubarb's shapes)
    std::vector<Cue> reducedCues;       // empty in a Rhubarb file
    std::vector<TimedPhoneme> phonemes; // empty in a Rhubarb file
    std::optional<TrackError> error;
    std::vector<TrackErrorCurvePoint> errorCurve;
    std::optional<TrackPlayback> playback; // keys and keyframes of both faces, for players
    bool operator==(const SpeechTrackFile&) const = default;
};

// Doubles are written so that they read back exactly.
std::string formatTrackJson(const SpeechTrackFile& track);
// The same text on one line, without the final newline: compactJsonText(formatTrackJson(track)),
// written directly (`say --stdin`).
std::string formatTrackJsonLine(const SpeechTrackFile& track);

// Throws InputError "<source>:<JSON path>: <what>" for malformed JSON, missing or mistyped fields,
// cues or phonemes that are not contiguous, negative or non-finite errors. Unknown metadata and
// top-level fields are ignored (Rhubarb writes its own).
SpeechTrackFile parseTrackJson(std::string_view text, std::string_view source);
SpeechTrackFile loadTrackJson(const std::filesystem::path& path);

} // namespace vl
