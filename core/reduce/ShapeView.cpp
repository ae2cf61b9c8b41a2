#include "core/reduce/ShapeView.h"

namespace vl {

ShapeView::ShapeView(const Vec3* data, std::size_t count, std::size_t vertices) {
    rows_.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
        rows_.emplace_back(std::span<const Vec3>(data + i * vertices, vertices));
}

ShapeView::ShapeView(const float* xyz, std::size_t count, std::size_t vertices) {
    rows_.reserve(count);
    for (std::size_t i = 0; i < count; ++i) rows_.emplace_back(xyz + 3 * i * vertices, vertices);
}

ShapeView::ShapeView(std::span<const std::vector<Vec3>> shapes) {
    rows_.reserve(shapes.size());
    for (const auto& shape : shapes) rows_.emplace_back(shape);
}

ShapeView::ShapeView(const std::vector<std::vector<Vec3>>& shapes)
    : ShapeView(std::span<const std::vector<Vec3>>(shapes)) {}

ShapeView::ShapeView(std::span<const std::span<const Vec3>> shapes) : rows_(shapes.begin(), shapes.end()) {}

} // namespace vl
