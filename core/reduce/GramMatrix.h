#pragma once
// The weighted Gram matrix the reduction objective depends on (see GroupCostModel.h).
#include "core/reduce/ShapeView.h"

#include <span>
#include <vector>

namespace vl {

// G_ij = sum_k w_k <a_ik - c_k, a_jk - c_k> (n x n, row-major), c = the frequency-weighted mean
// shape. Costs are translation-invariant per vertex; centring keeps D and Q/F small so their
// difference does not lose precision to cancellation. O(n^2 |V|), blocked over vertices and in
// parallel; the result does not depend on the thread count (fixed blocks, summed in block order).
// Requires n shapes of weights.size() vertices and frequencies with a positive sum.
std::vector<double> centredGram(const ShapeView& shapes, std::span<const double> frequencies,
                                std::span<const double> weights);

} // namespace vl
