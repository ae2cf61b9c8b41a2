#include "core/paint/PaintSurface.h"

#include "core/common/Error.h"

#include <algorithm>

namespace vl {

PaintSurface::PaintSurface(std::span<const Vec3> positions, std::span<const Triangle> triangles)
    : positions_(positions.begin(), positions.end()), triangles_(triangles.begin(), triangles.end()) {
    const std::size_t n = positions_.size();
    for (std::size_t f = 0; f < triangles_.size(); ++f)
        for (const std::uint32_t v : triangles_[f])
            if (v >= n)
                throwInputError("paint surface", "triangle " + std::to_string(f) + " names vertex " +
                                                     std::to_string(v) + " of " + std::to_string(n));
    normals_ = vertexNormals(positions_, triangles_);

    // Edge neighbours as compressed rows: count, prefix-sum, fill, then sort and dedupe each row.
    std::vector<std::uint32_t> degree(n, 0);
    for (const Triangle& t : triangles_)
        for (const std::uint32_t v : t) degree[v] += 2;
    offsets_.assign(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) offsets_[v + 1] = offsets_[v] + degree[v];
    std::vector<std::uint32_t> all(offsets_[n]);
    std::vector<std::uint32_t> fill(offsets_.begin(), offsets_.end() - 1);
    for (const Triangle& t : triangles_)
        for (int a = 0; a < 3; ++a) {
            const std::uint32_t v = t[static_cast<std::size_t>(a)];
            all[fill[v]++] = t[static_cast<std::size_t>((a + 1) % 3)];
            all[fill[v]++] = t[static_cast<std::size_t>((a + 2) % 3)];
        }
    neighbours_.reserve(all.size() / 2);
    std::vector<std::uint32_t> compact(n + 1, 0);
    for (std::size_t v = 0; v < n; ++v) {
        const auto begin = all.begin() + offsets_[v], end = all.begin() + offsets_[v + 1];
        std::sort(begin, end);
        const auto last = std::unique(begin, end);
        for (auto it = begin; it != last; ++it)
            if (*it != v) neighbours_.push_back(*it);
        compact[v + 1] = static_cast<std::uint32_t>(neighbours_.size());
    }
    offsets_ = std::move(compact);

    Vec3 lo, hi;
    if (bounds(positions_, lo, hi)) {
        size_ = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
        mirrorX_ = 0.5 * (lo[0] + hi[0]);
    }
}

std::uint32_t PaintSurface::nearestVertex(const Vec3& point) const {
    if (positions_.empty()) throwInputError("paint surface", "the mesh has no vertices");
    std::uint32_t best = 0;
    double bestDistance = (positions_[0] - point).sqrnorm();
    for (std::size_t v = 1; v < positions_.size(); ++v) {
        const double d = (positions_[v] - point).sqrnorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<std::uint32_t>(v);
        }
    }
    return best;
}

} // namespace vl
