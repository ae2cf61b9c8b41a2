#pragma once
// Per-vertex terms of the dissimilarity rho(A,B) = sum_k w_k |a_k - b_k|^2, i.e. where on the face
// a merged viseme differs from an original one (the editor's before/after error colour map).
#include "core/mesh/Mesh.h"

#include <span>
#include <vector>

namespace vl {

// e_k = w_k |a_k - b_k|^2; their sum is dissimilarity(a, b, w). Throws InputError on size mismatch.
std::vector<double> vertexErrors(std::span<const Vec3> a, std::span<const Vec3> b,
                                 std::span<const double> weights);

} // namespace vl
