#include "core/face/FaceDomain.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

namespace vl::face {

double mouthHoleHalfHeight(double u) {
    // The tolerance makes the corners exactly 0 although 0.5 - 0.1 is not exact in binary.
    const double t = std::abs(u - kMouthU) / kMouthHalfWidth;
    if (t >= 1.0 - 1e-12) return 0.0;
    return t <= kMouthFlat ? kMouthHalfHeight : kMouthHalfHeight * (1.0 - t) / (1.0 - kMouthFlat);
}

bool insideMouthHole(double u, double v) {
    // The tolerance keeps rim vertices (computed as kMouthV -/+ half-height) outside despite rounding.
    return std::abs(v - kMouthV) < mouthHoleHalfHeight(u) - 1e-12;
}

double squeezedMouthV(double u, double v, double closedGap) {
    constexpr double kReach = 0.035;
    const double h = mouthHoleHalfHeight(u);
    const double d = v - kMouthV;
    if (h == 0.0) return v;
    if (std::abs(d) < h) return kMouthV + closedGap * d;
    const double s = std::abs(d) - h;
    const double shift = (1.0 - closedGap) * h * std::exp(-(s / kReach) * (s / kReach));
    return v - std::copysign(shift, d);
}

namespace {

using Density = std::function<double(double)>;

// Grid line positions over [0,1] through every breakpoint, with segment lengths inversely
// proportional to `density` and about `resolution` segments in all.
std::vector<double> gridLines(const std::vector<double>& breaks, int resolution, const Density& density) {
    constexpr int kSteps = 4096; // numerical integration of the density
    std::vector<double> cumulative(kSteps + 1, 0.0);
    for (int s = 0; s < kSteps; ++s) cumulative[s + 1] = cumulative[s] + density((s + 0.5) / kSteps) / kSteps;
    const auto mass = [&](double x) {
        const double f = x * kSteps;
        const int s = std::min(static_cast<int>(f), kSteps - 1);
        return cumulative[s] + (cumulative[s + 1] - cumulative[s]) * (f - s);
    };
    const auto inverse = [&](double m) {
        const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), m);
        const int s = std::clamp(static_cast<int>(it - cumulative.begin()) - 1, 0, kSteps - 1);
        const double span = cumulative[s + 1] - cumulative[s];
        return (s + (span > 0.0 ? (m - cumulative[s]) / span : 0.0)) / kSteps;
    };
    const double total = cumulative.back();
    std::vector<double> lines{breaks.front()};
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
        const double m0 = mass(breaks[p]), m1 = mass(breaks[p + 1]);
        const int segments = std::max(1, static_cast<int>(std::lround((m1 - m0) / total * resolution)));
        for (int k = 1; k < segments; ++k) lines.push_back(inverse(m0 + (m1 - m0) * k / segments));
        lines.push_back(breaks[p + 1]);
    }
    return lines;
}

double domainBump(double x, double centre, double width) {
    return std::exp(-((x - centre) / width) * ((x - centre) / width));
}

// Moves vertices near the mouth line apart so the cut along it opens to the rhombus hole; the shift
// fades out linearly within kOpenReach of the mouth line (kOpenReach > kMouthHalfHeight keeps the
// grid rows in order).
constexpr double kOpenReach = 0.08;

double openedV(double u, double v, int side) {
    const double fade = std::max(0.0, 1.0 - std::abs(v - kMouthV) / kOpenReach);
    return v + side * mouthHoleHalfHeight(u) * fade;
}

} // namespace

MeshData faceDomainMesh(int resolution, DomainDensity density) {
    if (resolution < 10 || resolution > 4096)
        throwInputError("face domain", "resolution " + std::to_string(resolution) + " is outside 10..4096");
    const bool focused = density == DomainDensity::MouthFocused;
    // Relative line density: high at the mouth and eyes, low on the sides of the head and the top
    // of the forehead.
    const Density du = [focused](double u) {
        return focused ? 0.5 + 0.5 * domainBump(u, kMouthU, 0.3) + 1.0 * domainBump(u, kMouthU, 0.2) +
                             1.4 * domainBump(std::abs(u - kMouthU), 0.135, 0.05)
                       : 1.0;
    };
    const Density dv = [focused](double v) {
        return focused ? 0.6 + 0.4 * domainBump(v, 0.45, 0.3) + 2.5 * domainBump(v, kMouthV, 0.09) +
                             2.0 * domainBump(v, 0.585, 0.05)
                       : 1.0;
    };
    const auto us =
        gridLines({0.0, kMouthU - kMouthHalfWidth, kMouthU - kMouthFlat * kMouthHalfWidth, kMouthU,
                   kMouthU + kMouthFlat * kMouthHalfWidth, kMouthU + kMouthHalfWidth, 1.0},
                  resolution, du);
    const auto vs = gridLines({0.0, kMouthV, 1.0}, resolution, dv);
    const int nu = static_cast<int>(us.size()), nv = static_cast<int>(vs.size());
    const int mouthRow = static_cast<int>(std::find(vs.begin(), vs.end(), kMouthV) - vs.begin());
    const int centreColumn = static_cast<int>(std::find(us.begin(), us.end(), kMouthU) - us.begin());

    MeshData mesh;
    // index[j][i]: vertex of grid point (i,j) as seen from the cells above row j; lowerIndex for
    // the mouth row is what the cells below see (the cut between the lips).
    std::vector<std::uint32_t> index(static_cast<std::size_t>(nu) * nv);
    std::vector<std::uint32_t> lowerIndex(nu);
    const auto add = [&mesh](double u, double v) {
        mesh.uvs.emplace_back(u, v);
        mesh.positions.emplace_back(u, v, 0.0);
        return static_cast<std::uint32_t>(mesh.positions.size() - 1);
    };
    for (int j = 0; j < nv; ++j) {
        const int side = j < mouthRow ? -1 : 1;
        for (int i = 0; i < nu; ++i) {
            const double u = us[i];
            if (j == mouthRow) {
                lowerIndex[i] = add(u, openedV(u, vs[j], -1));
                index[static_cast<std::size_t>(j) * nu + i] = lowerIndex[i];
            } else {
                index[static_cast<std::size_t>(j) * nu + i] = add(u, openedV(u, vs[j], side));
            }
        }
        if (j == mouthRow) // upper copies of the cut vertices (strictly between the corners)
            for (int i = 0; i < nu; ++i)
                if (mouthHoleHalfHeight(us[i]) > 0.0)
                    index[static_cast<std::size_t>(j) * nu + i] = add(us[i], openedV(us[i], vs[j], 1));
    }
    for (int j = 0; j + 1 < nv; ++j)
        for (int i = 0; i + 1 < nu; ++i) {
            const auto at = [&](int ii, int jj) {
                return jj == mouthRow && j < mouthRow ? lowerIndex[ii]
                                                      : index[static_cast<std::size_t>(jj) * nu + ii];
            };
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            // Alternating diagonals, mirror-symmetric about the centre column.
            if (((i - centreColumn) + (j - mouthRow)) % 2 == 0) {
                mesh.triangles.push_back({a, b, c});
                mesh.triangles.push_back({a, c, d});
            } else {
                mesh.triangles.push_back({a, b, d});
                mesh.triangles.push_back({b, c, d});
            }
        }
    return mesh;
}

MeshData faceBaseDomain(int resolution) {
    return faceDomainMesh(resolution, DomainDensity::Uniform);
}

} // namespace vl::face
