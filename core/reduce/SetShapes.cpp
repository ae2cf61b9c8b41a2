#include "core/reduce/SetShapes.h"

#include <algorithm>
#include <stdexcept>

namespace vl {

int SetShapes::find(std::string_view name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

SetShapes shapesOf(const VisemeSet& set) {
    SetShapes out{&set.neutral, {}, {}};
    std::vector<std::span<const Vec3>> rows; // a view of the set's positions: no copy of the shapes
    rows.reserve(set.size());
    for (const Viseme& v : set.visemes) {
        out.names.push_back(v.name);
        rows.emplace_back(v.positions);
    }
    out.shapes = ShapeView(std::span<const std::span<const Vec3>>(rows));
    return out;
}

SetShapes shapesOf(const FloatVisemeSet& set) {
    return {&set.neutral, set.names, ShapeView(set.positions.get(), set.size(), set.vertexCount())};
}

void mergeKeyInto(const ShapeView& shapes, std::span<const double> frequencies, std::span<const int> members,
                  std::span<float> out) {
    if (members.empty()) throw std::invalid_argument("mergeKeyInto: empty group");
    double total = 0;
    for (const int i : members) total += frequencies[static_cast<std::size_t>(i)];
    std::vector<double> share;
    std::vector<ShapeRow> rows;
    for (const int i : members) {
        // As mergeGroup: zero-frequency groups take the plain mean.
        share.push_back(total > 0 ? frequencies[static_cast<std::size_t>(i)] / total : 1.0 / members.size());
        rows.push_back(shapes[static_cast<std::size_t>(i)]);
    }
    const std::size_t vertices = out.size() / 3;
    for (std::size_t v = 0; v < vertices; ++v) {
        Vec3 merged = rows[0][v];
        if (rows.size() > 1) {
            merged = Vec3(0, 0, 0);
            for (std::size_t k = 0; k < rows.size(); ++k) merged += share[k] * rows[k][v];
        }
        for (int axis = 0; axis < 3; ++axis)
            out[3 * v + static_cast<std::size_t>(axis)] = static_cast<float>(merged[axis]);
    }
}

} // namespace vl
