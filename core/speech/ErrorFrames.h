#pragma once
// Each speech error measure as a per-frame accumulator over FrameBlends, so one pass over the frames
// feeds one measure (UtteranceError.h, DisplacementError.h) or both (SpeechErrors.h).
#include "core/speech/DisplacementError.h"
#include "core/speech/FrameBlends.h"
#include "core/speech/UtteranceError.h"

#include <vector>

namespace vl {

class UtteranceErrorFrames {
  public:
    UtteranceErrorFrames(const SpeechErrorBasis& basis, const FrameBlends& frames, double fps);
    void add(std::size_t f); // after frames.load(f)
    UtteranceError finish();

  private:
    const SpeechErrorBasis& basis_;
    const FrameBlends& frames_;
    UtteranceError error_;
    std::vector<double> motion_, times_;
};

class DisplacementErrorFrames {
  public:
    // Throws InputError when every weight of the basis is 0 (there is no mouth).
    DisplacementErrorFrames(const SpeechErrorBasis& basis, const FrameBlends& frames, double fps,
                            const DisplacementUnit& unit);
    void add(std::size_t f); // after frames.load(f)
    DisplacementError finish();

  private:
    struct Column { // a frame's term with its coordinate arrays at hand
        double weight;
        const double *x, *y, *z;
        std::size_t index;
    };
    struct Sums {
        double square = 0;  // sum_v w_v |d_v|^2 over the mouth
        double largest = 0; // max_v |d_v|^2
        std::size_t largestLeaf = 0;
    };
    Sums frameSums(std::size_t startLeaf);
    double leafLargest(std::size_t begin, double* square) const;
    void childBounds(std::size_t level, std::size_t first, double (&bounds)[SpeechErrorBasis::kFanout]) const;

    const SpeechErrorBasis& basis_;
    const FrameBlends& frames_;
    double scale_;
    DisplacementError error_;
    Sums sums_;
    std::vector<Column> columns_;
    struct Pending { // a node put aside with its bound
        std::size_t level, node;
        double bound;
    };
    std::vector<Pending> stack_;
    double integral_ = 0, previousSquare_ = 0, previousTime_ = 0;
};

} // namespace vl
