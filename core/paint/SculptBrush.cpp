#include "core/paint/SculptBrush.h"

#include "core/common/Error.h"

#include <vector>

namespace vl {

std::string_view sculptToolName(SculptTool tool) {
    switch (tool) {
    case SculptTool::Grab:
        return "grab";
    case SculptTool::Smooth:
        return "smooth";
    case SculptTool::Inflate:
        return "inflate";
    case SculptTool::Deflate:
        return "deflate";
    }
    return "grab";
}

namespace {

// The footprint of one side of the dab (no mirror): WeightBrush's, from `eye` when front faces only.
std::vector<std::pair<std::uint32_t, double>> sideFootprint(const PaintSurface& surface, WeightBrush brush,
                                                            const Vec3& centre, std::optional<Vec3> eye) {
    brush.symmetric = false;
    brush.eye = eye;
    return brushFootprint(surface, brush, centre);
}

Vec3 mirrored(Vec3 p, double mirrorX) {
    p[0] = 2.0 * mirrorX - p[0];
    return p;
}

} // namespace

void applySculptDab(const PaintSurface& surface, std::span<const Vec3> neutral, const SculptDab& dab,
                    const Vec3& centre, std::span<Vec3> shape) {
    const std::size_t n = surface.vertexCount();
    if (neutral.size() != n || shape.size() != n)
        throwInputError("sculpt", "the shape (" + std::to_string(shape.size()) + " vertices), its neutral (" +
                                      std::to_string(neutral.size()) + ") and the surface (" +
                                      std::to_string(n) + ") differ in vertex count");
    const std::vector<Vec3> before(shape.begin(), shape.end());
    auto delta = [&](std::uint32_t v) { return before[v] - neutral[v]; };
    const double step = (dab.tool == SculptTool::Deflate ? -0.1 : 0.1) * dab.brush.radius;
    // side = +1 for the dab itself, -1 for its mirror image (the grab's x is negated there).
    auto apply = [&](const std::vector<std::pair<std::uint32_t, double>>& footprint, double side,
                     std::vector<double>& done) {
        for (const auto& [v, f] : footprint) {
            if (f <= done[v]) continue; // a vertex both sides reach moves once, by the larger factor
            const double extra = f - done[v];
            done[v] = f;
            switch (dab.tool) {
            case SculptTool::Grab:
                shape[v] += extra * Vec3(side * dab.grab[0], dab.grab[1], dab.grab[2]);
                break;
            case SculptTool::Smooth: {
                const auto around = surface.neighbours(v);
                if (around.empty()) break;
                Vec3 mean(0, 0, 0);
                for (const std::uint32_t w : around) mean += delta(w);
                mean /= static_cast<double>(around.size());
                shape[v] += extra * (mean - delta(v));
                break;
            }
            case SculptTool::Inflate:
            case SculptTool::Deflate:
                shape[v] += extra * step * surface.normals()[v];
                break;
            }
        }
    };
    std::vector<double> done(n, 0.0);
    apply(sideFootprint(surface, dab.brush, centre, dab.brush.eye), 1.0, done);
    if (dab.brush.symmetric) {
        const double x = dab.brush.mirrorX;
        const std::optional<Vec3> eye =
            dab.brush.eye ? std::optional<Vec3>(mirrored(*dab.brush.eye, x)) : std::nullopt;
        apply(sideFootprint(surface, dab.brush, mirrored(centre, x), eye), -1.0, done);
    }
}

} // namespace vl
