#pragma once
// A read-only view of n shapes (vertex position arrays) that copies nothing: one row per shape, each
// shape contiguous. It views one contiguous n x V block (as the CLI loads a viseme set: doubles, or
// float32 x, y, z for large sets, see FloatVisemeSet) or the separate position vectors of a VisemeSet
// or an editor document. Like std::span, it does not own the positions: they must outlive the view.
//
// Float32 rows are widened to double on access, so every sum over them is accumulated in double:
// a float32 input is exact in double, and what the solvers compute from it carries only double
// rounding (the float32 storage loses nothing a float32 file held). Inputs read as double and stored
// as float32 are rounded once, relative error <= 2^-24 per coordinate (FloatVisemeSet.h states what
// that does to costs).
#include "core/mesh/Mesh.h"

#include <cstddef>
#include <span>
#include <vector>

namespace vl {

// One shape: V positions stored as Vec3 (double) or as 3 float32 each.
class ShapeRow {
  public:
    ShapeRow() = default;
    ShapeRow(std::span<const Vec3> positions) // NOLINT(google-explicit-constructor)
        : data_(positions.data()), size_(positions.size()) {}
    ShapeRow(const std::vector<Vec3>& positions) // NOLINT(google-explicit-constructor)
        : ShapeRow(std::span<const Vec3>(positions)) {}
    ShapeRow(const float* xyz, std::size_t vertices) : data_(xyz), size_(vertices), isFloat_(true) {}

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    bool isFloat() const { return isFloat_; }
    Vec3 operator[](std::size_t v) const {
        if (isFloat_) {
            const float* p = static_cast<const float*>(data_) + 3 * v;
            return Vec3(p[0], p[1], p[2]);
        }
        return static_cast<const Vec3*>(data_)[v];
    }

  private:
    const void* data_ = nullptr;
    std::size_t size_ = 0;
    bool isFloat_ = false;
};

class ShapeView {
  public:
    ShapeView() = default;
    // `count` shapes of `vertices` positions each, stored one after the other from `data`.
    ShapeView(const Vec3* data, std::size_t count, std::size_t vertices);
    // The same with each position as 3 float32 (x, y, z): 12 bytes a position instead of 24.
    ShapeView(const float* xyz, std::size_t count, std::size_t vertices);
    // Implicit on purpose: every container of shapes can be passed where a view is expected.
    ShapeView(std::span<const std::vector<Vec3>> shapes);     // NOLINT(google-explicit-constructor)
    ShapeView(const std::vector<std::vector<Vec3>>& shapes);  // NOLINT(google-explicit-constructor)
    ShapeView(std::span<const std::span<const Vec3>> shapes); // NOLINT(google-explicit-constructor)

    std::size_t size() const { return rows_.size(); }
    bool empty() const { return rows_.empty(); }
    ShapeRow operator[](std::size_t i) const { return rows_[i]; }

  private:
    std::vector<ShapeRow> rows_;
};

} // namespace vl
