#pragma once
// The frames both speech error measures read (UtteranceError.h, DisplacementError.h): at
// t = f / fps the blends of the full and the reduced face as coefficients of the error basis
// (SpeechErrorBasis.h). Evaluated once per frame, so one pass can feed both measures.
#include "core/speech/FaceTrack.h"
#include "core/speech/SpeechErrorBasis.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vl {

// A basis vector with its nonzero coefficient.
struct BasisTerm {
    std::size_t index;
    double weight;
    bool operator==(const BasisTerm&) const = default;
};

class FrameBlends {
  public:
    // Throws InputError, naming `measure`, for fps <= 0 or a basis made for faces of other key or
    // vertex counts.
    FrameBlends(const SpeechErrorBasis& basis, const FaceTrack& full, const FaceTrack& reduced, double fps,
                const std::string& measure);

    // Frames f = 0 .. ceil(duration * fps), the last at the end of the longer track.
    std::size_t frameCount() const { return frameCount_; }
    double duration() const { return duration_; }
    double time(std::size_t f) const;

    // Evaluates frame f (in increasing order): difference() is F(t) - R(t) and motion() is
    // F(t) - neutral, as nonzero coefficients in basis order; repeats() tells a frame whose difference
    // equals the frame before it (a held pose), which a measure may take from that frame.
    void load(std::size_t f);
    const std::vector<BasisTerm>& difference() const { return difference_; }
    const std::vector<BasisTerm>& motion() const { return motion_; }
    bool repeats() const { return repeats_; }
    // The difference's c^T G c (not clamped: it may cancel to a slightly negative value) and its scale
    // sum_a |c_a| sqrt(G_aa), the size of the terms it sums; evaluated once for every measure.
    double differenceForm() const { return differenceForm_; }
    double differenceScale() const { return differenceScale_; }

  private:
    const SpeechErrorBasis& basis_;
    const FaceTrack& full_;
    const FaceTrack& reduced_;
    double fps_;
    double duration_;
    std::size_t frameCount_;
    std::vector<double> fullCoefficients_, reducedCoefficients_;
    std::vector<BasisTerm> difference_, previous_, motion_;
    bool repeats_ = false;
    double differenceForm_ = 0, differenceScale_ = 0;
};

// c^T G c with G the basis's Gram matrix: sum_v w_v |d(v)|^2 of the frame d = sum_a c_a b_a. Not
// clamped: rounding may make a zero distance slightly negative.
double gramForm(const SpeechErrorBasis& basis, const std::vector<BasisTerm>& terms);

} // namespace vl
