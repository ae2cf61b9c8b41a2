#include "core/paint/VertexVisibility.h"

#include "core/paint/RayPick.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace vl {
namespace {

struct Projected {
    double x = 0.0, y = 0.0;
    bool inFront = false; // clip w > 0: the projection is defined
};

Projected project(const std::array<double, 16>& m, const Vec3& p) {
    // Column-major: element (row r, column c) is m[4 c + r].
    auto row = [&](int r) { return m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]; };
    const double w = row(3);
    if (!(w > 1e-12)) return {};
    return {row(0) / w, row(1) / w, true};
}

// Widens the projected boxes so rounding (a view-projection matrix in float, as the GPU's) never
// drops a triangle whose projection covers a point: 1e-4 of the half screen, far above float's error.
constexpr double kMargin = 1e-4;

} // namespace

VertexVisibility::VertexVisibility(const PaintSurface& surface, const std::array<double, 16>& viewProjection,
                                   const Vec3& eye)
    : surface_(&surface), viewProjection_(viewProjection), eye_(eye) {
    const auto& triangles = surface.triangles();
    // About two triangles per cell on a mesh filling the screen.
    cells_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(triangles.size()) / 2.0)), 1, 512);
    const auto total = static_cast<std::size_t>(cells_) * static_cast<std::size_t>(cells_);
    auto cellIndex = [&](double ndc) {
        return std::clamp(static_cast<int>(std::floor((ndc + 1.0) * 0.5 * cells_)), 0, cells_ - 1);
    };
    // Two passes over the triangles' cell ranges: count, then fill (CSR).
    struct Range {
        int x0, y0, x1, y1;
    };
    std::vector<Range> ranges(triangles.size(), Range{0, 0, -1, -1});
    std::vector<std::uint32_t> counts(total + 1, 0);
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        constexpr double kInf = std::numeric_limits<double>::infinity();
        double xMin = kInf, xMax = -kInf, yMin = kInf, yMax = -kInf;
        bool inFront = true;
        for (const std::uint32_t v : triangles[f]) {
            const Projected p = project(viewProjection_, surface.positions()[v]);
            inFront = inFront && p.inFront;
            xMin = std::min(xMin, p.x), xMax = std::max(xMax, p.x);
            yMin = std::min(yMin, p.y), yMax = std::max(yMax, p.y);
        }
        if (!inFront) { // its projection wraps around: test it everywhere
            everywhere_.push_back(static_cast<std::uint32_t>(f));
            continue;
        }
        xMin -= kMargin, yMin -= kMargin, xMax += kMargin, yMax += kMargin;
        if (xMax < -1.0 || xMin > 1.0 || yMax < -1.0 || yMin > 1.0) continue; // hides nothing on screen
        const Range r{cellIndex(xMin), cellIndex(yMin), cellIndex(xMax), cellIndex(yMax)};
        const auto covered =
            static_cast<std::size_t>(r.x1 - r.x0 + 1) * static_cast<std::size_t>(r.y1 - r.y0 + 1);
        if (4 * covered > total && total > 4) { // near the camera: cheaper tested everywhere than binned
            everywhere_.push_back(static_cast<std::uint32_t>(f));
            continue;
        }
        ranges[f] = r;
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x) ++counts[static_cast<std::size_t>(y * cells_ + x) + 1];
    }
    for (std::size_t c = 0; c < total; ++c) counts[c + 1] += counts[c];
    offsets_ = counts;
    binned_.resize(offsets_.back());
    std::vector<std::uint32_t> next(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const Range& r = ranges[f];
        for (int y = r.y0; y <= r.y1; ++y)
            for (int x = r.x0; x <= r.x1; ++x)
                binned_[next[static_cast<std::size_t>(y * cells_ + x)]++] = static_cast<std::uint32_t>(f);
    }
}

int VertexVisibility::cellAt(double ndcX, double ndcY) const {
    if (!(ndcX >= -1.0 && ndcX <= 1.0 && ndcY >= -1.0 && ndcY <= 1.0)) return -1;
    auto index = [&](double ndc) {
        return std::clamp(static_cast<int>(std::floor((ndc + 1.0) * 0.5 * cells_)), 0, cells_ - 1);
    };
    return index(ndcY) * cells_ + index(ndcX);
}

bool VertexVisibility::hiddenBy(std::uint32_t v, std::uint32_t triangle) const {
    const Triangle& t = surface_->triangles()[triangle];
    if (t[0] == v || t[1] == v || t[2] == v) return false;
    const auto& positions = surface_->positions();
    const Vec3 towards = positions[v] - eye_;
    const double distance = towards.norm();
    if (!(distance > 0.0)) return false;
    const auto hit =
        intersectTriangle(positions[t[0]], positions[t[1]], positions[t[2]], eye_, towards / distance);
    return hit && hit->distance > 0.0 && hit->distance < distance * (1.0 - 1e-6);
}

bool VertexVisibility::visible(std::uint32_t v) const {
    if (v >= surface_->vertexCount())
        throwInputError("visibility",
                        "vertex " + std::to_string(v) + " of " + std::to_string(surface_->vertexCount()));
    for (const std::uint32_t f : everywhere_)
        if (hiddenBy(v, f)) return false;
    const Projected p = project(viewProjection_, surface_->positions()[v]);
    const int cell = p.inFront ? cellAt(p.x, p.y) : -1;
    if (cell < 0) { // off the screen: no bins there
        for (std::uint32_t f = 0; f < surface_->triangles().size(); ++f)
            if (hiddenBy(v, f)) return false;
        return true;
    }
    for (std::uint32_t i = offsets_[static_cast<std::size_t>(cell)];
         i < offsets_[static_cast<std::size_t>(cell) + 1]; ++i)
        if (hiddenBy(v, binned_[i])) return false;
    return true;
}

std::vector<std::uint32_t> visibleVertices(const PaintSurface& surface,
                                           std::span<const std::uint32_t> vertices,
                                           const std::array<double, 16>& viewProjection, const Vec3& eye) {
    std::vector<std::uint32_t> seen;
    if (vertices.empty()) return seen;
    const VertexVisibility visibility(surface, viewProjection, eye);
    for (const std::uint32_t v : vertices)
        if (visibility.visible(v)) seen.push_back(v);
    return seen;
}

} // namespace vl
