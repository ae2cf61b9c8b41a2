#pragma once
// A read-only view of n shapes (vertex position arrays) that copies nothing: one pointer per shape,
// each shape contiguous. It views one contiguous n x V block (as the CLI loads a viseme set) or the
// separate position vectors of a VisemeSet or an editor document. Like std::span, it does not own
// the positions: they must outlive the view.
#include "core/mesh/Mesh.h"

#include <cstddef>
#include <span>
#include <vector>

namespace vl {

class ShapeView {
  public:
    ShapeView() = default;
    // `count` shapes of `vertices` positions each, stored one after the other from `data`.
    ShapeView(const Vec3* data, std::size_t count, std::size_t vertices);
    // Implicit on purpose: every container of shapes can be passed where a view is expected.
    ShapeView(std::span<const std::vector<Vec3>> shapes);     // NOLINT(google-explicit-constructor)
    ShapeView(const std::vector<std::vector<Vec3>>& shapes);  // NOLINT(google-explicit-constructor)
    ShapeView(std::span<const std::span<const Vec3>> shapes); // NOLINT(google-explicit-constructor)

    std::size_t size() const { return rows_.size(); }
    bool empty() const { return rows_.empty(); }
    std::span<const Vec3> operator[](std::size_t i) const { return rows_[i]; }

  private:
    std::vector<std::span<const Vec3>> rows_;
};

} // namespace vl
