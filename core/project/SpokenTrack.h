#pragma once
// One utterance spoken by a SpeakingFace: its tracks on the full and the reduced face, their
// utterance and displacement errors, the track file (without the error curve) and the animated GLB.
// `say` and `visemelab batch` make their outputs here, so a batch job writes the same bytes as the
// single command.
#include "core/project/SpeakingFace.h"
#include "core/runtime/Animation.h"
#include "core/speech/FaceTrack.h"
#include "core/speech/TrackJson.h"
#include "core/speech/Utterance.h"

#include <filesystem>
#include <string>

namespace vl {

// What the track file records of the run.
struct SpokenTrackOptions {
    std::filesystem::path out; // the track file: the WAV is named relative to it
    std::filesystem::path wav; // "" when none
    std::string textFile;      // the corpus spoken, "" for inline text
    std::string voice;
    int wordsPerMinute = 0;
    std::string project; // as the user named it, "" for an avatar
    runtime::Interpolation interpolation = runtime::Interpolation::Cubic;
    double fps = 60;
};

struct SpokenTrack {
    FaceTrack full, reduced;
    SpeechTrackFile file;
};

// Throws InputError (at the face) for phonemes the faces do not map.
SpokenTrack spokenTrack(const SpeakingFace& face, const Utterance& utterance,
                        const SpokenTrackOptions& options, const std::string& text);

// The face the --glb file (and the say page) shows: the avatar itself animated (its reduced face
// when reduced), else the reduced face with a morph weight animation.
std::string spokenGlb(const SpeakingFace& face, const SpokenTrack& spoken, double fps);

} // namespace vl
