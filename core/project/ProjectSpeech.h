#pragma once
// A project's faces for speech: the full viseme set and its reduction as models with phoneme maps,
// the vertex weights its reduction uses, and the utterance error of every possible reduction.
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReducedModel.h"
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

// `map`, when given, says which viseme each phoneme shows instead of the project's own map (needed
// when the project's frequencies are given per viseme). Throws InputError naming the project when
// there is no map at all, naming the map for visemes it names that the project lacks, and for
// anything loadProjectVisemeSet or the reduction refuses.
SpeechFaces projectSpeechFaces(const Project& project, const PhonemeVisemeMap* map = nullptr);

// Replaces the model's phoneme -> key map: each phoneme goes to the key whose members include its
// viseme (a viseme of model.resting: kRestingKey, the neutral face). Throws InputError at `where`
// listing the visemes of `map` that no key holds and that do not rest.
void setPhonemeMap(ReducedModel& model, const PhonemeVisemeMap& map, std::string_view where);

struct ErrorCurvePoint {
    int m = 0;            // number of keys
    double cost = 0;      // the reduction's optimal rho_f for m
    UtteranceError error; // of the phonemes spoken by that reduction against the full set
};

// For m = 1 .. n (n - 1 when the rest is free: the rest viseme is no key): the optimal reduction to m
// keys with the project's frequencies, weights and rest model, and the utterance error of `phonemes`
// on it. `progress` gets values in [0, 1].
std::vector<ErrorCurvePoint> projectErrorCurve(const Project& project, std::span<const TimedPhoneme> phonemes,
                                               const PlaybackSettings& settings, double fps,
                                               const ProgressCallback& progress = {},
                                               const PhonemeVisemeMap* map = nullptr);

} // namespace vl
