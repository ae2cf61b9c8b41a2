#pragma once
// What a player needs to show a track exactly as VisemeLab plays it: the keys (by name, with the
// viseme names merged into each) and the runtime's keyframes over them (core/runtime/Animation.h),
// for the full and the reduced face. Written into the track JSON ("playback"), so a player in
// another language (app/web/visemelab-player.js) evaluates the same KeyframeCurve without knowing
// phonemes, holds or dominance values.
#include "core/runtime/Animation.h"

#include <string>
#include <vector>

namespace vl {

class FaceTrack;

struct PlaybackKey {
    std::string name;                 // the key's (target's) name
    std::vector<std::string> members; // viseme names merged into it (just `name` when unreduced)
    bool operator==(const PlaybackKey&) const = default;
};

struct PlaybackKeyframe {
    double time = 0;      // seconds
    int key = -1;         // index into the face's keys, -1 for the rest pose (all weights 0)
    double dominance = 1; // the dominance magnitude (Interpolation::Dominance only)
    bool operator==(const PlaybackKeyframe&) const = default;
};

struct FacePlayback {
    std::vector<PlaybackKey> keys;
    std::vector<PlaybackKeyframe> keyframes;
    bool operator==(const FacePlayback&) const = default;
};

struct TrackPlayback {
    std::string interpolation = "cubic"; // "linear", "cubic", "dominance"
    double dominanceRate = runtime::kDefaultDominanceRate;
    FacePlayback full, reduced;
    bool operator==(const TrackPlayback&) const = default;
};

// The keys and keyframes of a face track, as its runtime curve holds them.
FacePlayback playbackOf(const FaceTrack& face);

// The runtime curve of a face's playback (the evaluator every VisemeLab front end uses). Throws
// InputError at `where` when the keyframes are not a valid curve (KeyframeCurve::setKeyframes).
runtime::KeyframeCurve curveOf(const FacePlayback& face, const TrackPlayback& playback,
                               std::string_view where);

} // namespace vl
