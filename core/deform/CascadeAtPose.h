#pragma once
// A deformation cascade at one parameter vector (pose), evaluated at any (u,v) - the sampling
// function of adaptive refinement, called for every contour sample. Influence regions are zero
// outside their boxes and stages with q = 0 add nothing, so a grid of cells over the (u,v) square
// lists, per cell, only the stages and regions that can be non-zero there. at() returns what
// DeformationCascade::evaluateUnchecked returns, to the bit: the same non-zero terms are added in the
// same order, and a skipped term is an exact zero.
#include "core/deform/DeformationCascade.h"

#include <cstdint>
#include <span>
#include <vector>

namespace vl {

class CascadeAtPose {
  public:
    CascadeAtPose() = default;
    // Indexes `cascade` at q. q is not checked (callers check it with checkParameterValues) and must
    // have one value per parameter.
    CascadeAtPose(const DeformationCascade& cascade, std::span<const double> q);

    // The cascade's point at (u,v). `cascade` must be the one indexed (unchanged since); it is passed
    // in rather than kept by address so that the owner can be copied and moved freely.
    Vec3 at(const DeformationCascade& cascade, double u, double v) const;

  private:
    // One entry of a cell's list: the start of a stage (region < 0: its sampled part) or one of its
    // influence regions. A stage's regions follow its start, in the stage's order.
    struct Term {
        std::uint32_t stage;
        std::int32_t region;
    };
    std::vector<double> q_;
    std::vector<std::uint32_t> cellStart_; // kCells^2 + 1 offsets into terms_
    std::vector<Term> terms_;
};

} // namespace vl
