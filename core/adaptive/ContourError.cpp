#include "core/adaptive/ContourError.h"

#include "core/common/Error.h"

#include <algorithm>

namespace vl {

std::vector<Vec3> contourSamplePattern(int n) {
    std::vector<Vec3> pattern;
    pattern.reserve(static_cast<std::size_t>(n) * n);
    const double scale = 1.0 / (3.0 * n);
    // Grid cell (i,j) has an upward sub-triangle (and a downward one when i + j <= n - 2); their
    // centroids in the first two barycentric coordinates are ((3i+1), (3j+1)) and ((3i+2), (3j+2)) / 3n.
    for (int i = 0; i < n; ++i) {
        for (int j = 0; i + j < n; ++j) {
            const double b1 = (3 * i + 1) * scale, b2 = (3 * j + 1) * scale;
            pattern.emplace_back(1.0 - b1 - b2, b1, b2);
            if (i + j <= n - 2) {
                const double c1 = (3 * i + 2) * scale, c2 = (3 * j + 2) * scale;
                pattern.emplace_back(1.0 - c1 - c2, c1, c2);
            }
        }
    }
    return pattern;
}

namespace {

// The error at barycentric point w: the surface against the triangle's linear interpolation (eq. 5).
double sampleError(const Surface& surface, const std::array<Vec2, 3>& uv, const std::array<Vec3, 3>& p,
                   const Vec3& w) {
    const Vec2 at = w[0] * uv[0] + w[1] * uv[1] + w[2] * uv[2];
    const Vec3 linear = w[0] * p[0] + w[1] * p[1] + w[2] * p[2];
    return (surface.sample(at) - linear).norm();
}

} // namespace

TriangleError triangleContourError(const Surface& surface, const std::array<Vec2, 3>& uv,
                                   const std::array<Vec3, 3>& p, const std::vector<Vec3>& pattern) {
    TriangleError error;
    double sum = 0.0;
    for (const auto& w : pattern) {
        const double e = sampleError(surface, uv, p, w);
        sum += e;
        error.maximum = std::max(error.maximum, e);
    }
    error.average = pattern.empty() ? 0.0 : sum / static_cast<double>(pattern.size());
    return error;
}

bool triangleContourErrorExceeds(const Surface& surface, const std::array<Vec2, 3>& uv,
                                 const std::array<Vec3, 3>& p, const std::vector<Vec3>& pattern,
                                 double averageLimit, double maximumLimit) {
    if (pattern.empty()) return 0.0 > averageLimit || 0.0 > maximumLimit;
    const auto count = static_cast<double>(pattern.size());
    double sum = 0.0;
    for (const auto& w : pattern) {
        const double e = sampleError(surface, uv, p, w);
        if (e > maximumLimit) return true;
        sum += e;
        if (sum / count > averageLimit) return true; // the remaining samples only add
    }
    return false;
}

ContourErrorStats measureContourError(const MeshData& mesh, const Surface& surface, int samplesPerSide) {
    if (!mesh.hasUVs()) throwInputError("contour error", "the mesh has no (u,v) coordinates");
    const auto pattern = contourSamplePattern(samplesPerSide);
    ContourErrorStats stats;
    double weighted = 0.0, area = 0.0;
    for (const auto& t : mesh.triangles) {
        const std::array<Vec2, 3> uv{mesh.uvs[t[0]], mesh.uvs[t[1]], mesh.uvs[t[2]]};
        const std::array<Vec3, 3> p{mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
        const Vec2 e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
        const double a = 0.5 * std::abs(e1[0] * e2[1] - e1[1] * e2[0]);
        const TriangleError error = triangleContourError(surface, uv, p, pattern);
        weighted += a * error.average;
        area += a;
        stats.maximum = std::max(stats.maximum, error.maximum);
        stats.samples += pattern.size();
    }
    stats.average = area > 0 ? weighted / area : 0.0;
    return stats;
}

} // namespace vl
