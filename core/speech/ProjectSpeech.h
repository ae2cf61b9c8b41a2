#pragma once
// A project's faces for speech: the full viseme set and its reduction as models with phoneme maps,
// the vertex weights its reduction uses, and the utterance error of every possible reduction.
#include "core/export/ReducedModel.h"
#include "core/reduce/Reduction.h"
#include "core/speech/UtteranceError.h"

#include <span>
#include <vector>

namespace vl {

struct Project;

struct SpeechFaces {
    ReducedModel full;           // every viseme its own key
    ReducedModel reduced;        // the project's reduction at its target m
    std::vector<double> weights; // per vertex, the project's weight mode
};

// Throws InputError naming the project when its frequencies carry no phoneme -> viseme map
// (frequencies given per viseme: nothing says which viseme a phoneme shows), and for anything
// loadProjectVisemeSet or the reduction refuses.
SpeechFaces projectSpeechFaces(const Project& project);

struct ErrorCurvePoint {
    int m = 0;            // number of keys
    double cost = 0;      // the reduction's optimal rho_f for m
    UtteranceError error; // of the phonemes spoken by that reduction against the full set
};

// For m = 1 .. n: the optimal reduction to m keys with the project's frequencies and weights,
// and the utterance error of `phonemes` on it. `progress` gets values in [0, 1].
std::vector<ErrorCurvePoint> projectErrorCurve(const Project& project, std::span<const TimedPhoneme> phonemes,
                                               const PlaybackSettings& settings, double fps,
                                               const ProgressCallback& progress = {});

} // namespace vl
