#pragma once
// Whole-mesh evaluation of a deformation cascade for interactive sliders. The fields are sampled once
// per mesh (or cascade) change; afterwards a parameter change costs one weighted sum per vertex:
//   p_i = base_i + sum_k q_k * W_k,i
// where W_k,i sums the samples of every AddVector stage driven by parameter k. Influence regions are
// zero outside their ellipses, so each W_k is stored sparsely (structure of arrays: vertex index,
// x, y, z in contiguous arrays, sorted by vertex) and cut into vertex blocks that run in parallel.
#include "core/deform/DeformationCascade.h"

#include <cstdint>
#include <span>
#include <vector>

namespace vl {

class CascadeSampler {
  public:
    CascadeSampler() = default;
    // Samples every stage of `cascade` at `uvs` (validates the cascade first).
    CascadeSampler(const DeformationCascade& cascade, std::span<const Vec2> uvs);

    std::size_t vertexCount() const { return baseX_.size(); }
    // Number of stored non-zero samples of parameter k (its support on this mesh).
    std::size_t supportSize(std::size_t parameter) const { return fields_[parameter].index.size(); }

    // Writes every vertex position for q into `out` (size vertexCount()). Checks q like
    // checkParameterValues; parameters whose value is 0 cost nothing.
    void evaluate(std::span<const double> q, std::span<Vec3> out) const;
    std::vector<Vec3> evaluate(std::span<const double> q) const;

  private:
    struct SparseField {
        std::vector<std::uint32_t> index; // vertex indices, increasing
        std::vector<double> x, y, z;
        std::vector<std::uint32_t> blockStart; // first entry of each vertex block, plus the end
    };
    void evaluateBlock(std::size_t block, std::span<const double> q, std::span<Vec3> out) const;

    DeformationCascade ranges_; // parameters only (names and ranges, for checking q)
    std::vector<double> baseX_, baseY_, baseZ_;
    std::vector<SparseField> fields_;
};

} // namespace vl
