#include "core/paint/PaintRegions.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <cmath>

namespace vl {
namespace {

void checkValues(const PaintSurface& surface, std::span<const double> values, const char* where) {
    if (values.size() != surface.vertexCount())
        throwInputError(where, std::to_string(values.size()) + " values for " +
                                   std::to_string(surface.vertexCount()) + " vertices");
}

} // namespace

std::vector<std::uint32_t> connectedRegion(const PaintSurface& surface, std::span<const double> values,
                                           std::uint32_t seed, double tolerance) {
    checkValues(surface, values, "region fill");
    if (seed >= surface.vertexCount())
        throwInputError("region fill", "seed vertex " + std::to_string(seed) + " of " +
                                           std::to_string(surface.vertexCount()));
    if (!(tolerance >= 0.0))
        throwInputError("region fill", "tolerance must be >= 0, got " + formatDouble(tolerance));
    const double reference = values[seed];
    std::vector<char> seen(surface.vertexCount(), 0);
    std::vector<std::uint32_t> stack = {seed}, region;
    seen[seed] = 1;
    while (!stack.empty()) {
        const std::uint32_t v = stack.back();
        stack.pop_back();
        region.push_back(v);
        for (const std::uint32_t w : surface.neighbours(v))
            if (!seen[w] && std::abs(values[w] - reference) <= tolerance) {
                seen[w] = 1;
                stack.push_back(w);
            }
    }
    std::sort(region.begin(), region.end());
    return region;
}

std::vector<std::uint32_t> verticesInRectangle(const PaintSurface& surface, const std::array<double, 16>& m,
                                               const NdcRectangle& rectangle, const std::optional<Vec3>& eye,
                                               bool flipped) {
    const double xMin = std::min(rectangle.x0, rectangle.x1), xMax = std::max(rectangle.x0, rectangle.x1);
    const double yMin = std::min(rectangle.y0, rectangle.y1), yMax = std::max(rectangle.y0, rectangle.y1);
    const auto& positions = surface.positions();
    const auto& normals = surface.normals();
    std::vector<std::uint32_t> inside;
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const Vec3& p = positions[v];
        // Column-major: element (row r, column c) is m[4 c + r].
        auto row = [&](int r) { return m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r]; };
        const double w = row(3);
        if (!(w > 0.0)) continue;
        const double x = row(0) / w, y = row(1) / w, z = row(2) / w;
        if (x < xMin || x > xMax || y < yMin || y > yMax || z < -1.0 || z > 1.0) continue;
        if (eye) {
            const double facing = OpenMesh::dot(normals[v], *eye - p);
            if (flipped ? !(facing < 0.0) : !(facing > 0.0)) continue;
        }
        inside.push_back(static_cast<std::uint32_t>(v));
    }
    return inside;
}

bool facesAwayAt(const PaintSurface& surface, const Vec3& point, const Vec3& eye) {
    const std::uint32_t v = surface.nearestVertex(point);
    return OpenMesh::dot(surface.normals()[v], eye - surface.positions()[v]) < 0.0;
}

double valueAt(const PaintSurface& surface, std::span<const double> values, std::size_t triangle,
               const Vec3& barycentric) {
    checkValues(surface, values, "weight readout");
    if (triangle >= surface.triangles().size())
        throwInputError("weight readout", "triangle " + std::to_string(triangle) + " of " +
                                              std::to_string(surface.triangles().size()));
    const Triangle& t = surface.triangles()[triangle];
    return barycentric[0] * values[t[0]] + barycentric[1] * values[t[1]] + barycentric[2] * values[t[2]];
}

std::vector<double> filled(std::vector<double> values, std::span<const std::uint32_t> vertices,
                           double value) {
    for (const std::uint32_t v : vertices) {
        if (v >= values.size())
            throwInputError("fill", "vertex " + std::to_string(v) + " of " + std::to_string(values.size()));
        values[v] = value;
    }
    return values;
}

} // namespace vl
