#pragma once
// How far the reduced face's mouth is from the full face's while they speak the same phonemes:
// at each frame the weighted squared distance of the reduction, rho(F(t), R(t)) =
// sum_k w_k |f_k(t) - r_k(t)|^2 (Danihelka et al., eq. 2 with vertex weights), and its time
// average over the utterance. Frequency-free: the speech itself says how often and how long each
// viseme is seen. With every phoneme held for its whole duration the mean would be
// sum_i (time share of viseme i) * rho(A_i, B_group(i)), the reduction's own cost rho_f with time
// shares for frequencies; blending adds the transitions.
#include "core/speech/FaceTrack.h"
#include "core/speech/SpeechErrorBasis.h"

#include <span>
#include <vector>

namespace vl {

struct UtteranceError {
    double fps = 0;             // frames per second of `frames`
    std::vector<double> frames; // rho at t = f / fps, f = 0 .. ceil(duration * fps) (last at the end)
    double mean = 0;            // (1/T) * integral of rho over [0, T] (trapezoid rule over the frames)
    double max = 0;
    double maxTime = 0; // seconds
    // The same time average of the full mouth's motion, rho(F(t), neutral), and mean / motion:
    // the share of the motion lost, comparable across faces of any size.
    double motion = 0;
    double relative = 0;
};

// `full` and `reduced` must be tracks of the same phonemes on faces with the same neutral mesh;
// `vertexWeights` one per vertex (computeWeights). Exact per frame up to rounding: every frame is
// c^T G c with G the weighted Gram matrix of the key displacements of both faces and c the (at
// most 8) blend weights (full minus reduced), so a frame costs O(1) instead of O(vertices).
// Throws InputError for mismatched sizes or fps <= 0.
UtteranceError measureUtteranceError(const FaceTrack& full, const FaceTrack& reduced,
                                     std::span<const double> vertexWeights, double fps);
// The same with the faces' basis made once (SpeechErrorBasis.h: many utterances on one face). Throws
// InputError when `basis` was made for faces of other key or vertex counts.
UtteranceError measureUtteranceError(const SpeechErrorBasis& basis, const FaceTrack& full,
                                     const FaceTrack& reduced, double fps);

} // namespace vl
