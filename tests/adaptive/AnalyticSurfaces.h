#pragma once
// Analytic test surfaces on simple (u,v) base domains, so the adaptive mesh is tested without the
// face model: a tilted plane, a sphere cap and a bumpy height field (with an amplitude parameter, to
// test re-adaptation), on grids with different diagonals, a jittered grid, a domain with a hole and
// a fan.
#include "core/adaptive/Surface.h"

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace vl::test {

enum class Diagonals { Alternating, Same, Random };

// nx x ny cells over [0,1]^2, two triangles per cell; jitter moves interior vertices by up to
// jitter * cell size (fixed seed), optionally with the cells inside [0.3,0.7]^2 removed (a hole).
inline MeshData gridDomain(int nx, int ny, Diagonals diagonals, double jitter = 0.0, bool hole = false,
                           unsigned seed = 1) {
    MeshData d;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> offset(-jitter, jitter);
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            Vec2 uv(double(i) / nx, double(j) / ny);
            if (i > 0 && i < nx && j > 0 && j < ny) {
                // Drawn in a fixed order (v first, as GCC evaluated the former one-expression form):
                // argument order is unspecified, and clang's order made seed 14 a grid with an inverted
                // triangle, which makeRbmtBase rightly refuses.
                const double dv = offset(rng);
                const double du = offset(rng);
                uv += Vec2(du / nx, dv / ny);
            }
            d.uvs.push_back(uv);
            d.positions.emplace_back(uv[0], uv[1], 0.0);
        }
    }
    std::bernoulli_distribution coin(0.5);
    auto id = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const double cu = (i + 0.5) / nx, cv = (j + 0.5) / ny;
            if (hole && cu > 0.3 && cu < 0.7 && cv > 0.3 && cv < 0.7) continue;
            bool up = true;
            if (diagonals == Diagonals::Alternating) up = (i + j) % 2 == 0;
            if (diagonals == Diagonals::Random) up = coin(rng);
            const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), e = id(i, j + 1);
            if (up) {
                d.triangles.push_back({a, b, c});
                d.triangles.push_back({a, c, e});
            } else {
                d.triangles.push_back({a, b, e});
                d.triangles.push_back({b, c, e});
            }
        }
    }
    return d;
}

// A regular polygon of `sides` corners around a centre vertex (all triangles touch the border).
inline MeshData fanDomain(int sides) {
    MeshData d;
    d.uvs.emplace_back(0.5, 0.5);
    for (int k = 0; k < sides; ++k) {
        const double a = 2 * M_PI * k / sides;
        d.uvs.emplace_back(0.5 + 0.4 * std::cos(a), 0.5 + 0.4 * std::sin(a));
    }
    for (int k = 0; k < sides; ++k)
        d.triangles.push_back(
            {0u, static_cast<std::uint32_t>(1 + k), static_cast<std::uint32_t>(1 + (k + 1) % sides)});
    return d;
}

// A surface given by a function of (u,v).
class FunctionSurface : public Surface {
  public:
    FunctionSurface(MeshData domain, std::function<Vec3(const Vec2&)> f)
        : domain_(std::move(domain)), f_(std::move(f)) {}
    const MeshData& baseDomain() const override { return domain_; }
    Vec3 sample(const Vec2& uv) const override { return f_(uv); }

  private:
    MeshData domain_;
    std::function<Vec3(const Vec2&)> f_;
};

inline Vec3 tiltedPlane(const Vec2& uv) {
    return Vec3(uv[0], uv[1], 0.3 * uv[0] - 0.2 * uv[1]);
}

inline Vec3 sphereCap(const Vec2& uv) {
    const double x = uv[0] - 0.5, y = uv[1] - 0.5;
    return Vec3(x, y, std::sqrt(1.0 - x * x - y * y));
}

// A height field with a sharp bump and ripples; `amplitude` scales the relief (0 = flat).
class BumpySurface : public Surface {
  public:
    explicit BumpySurface(MeshData domain, double amplitude = 1.0)
        : domain_(std::move(domain)), amplitude_(amplitude) {}
    const MeshData& baseDomain() const override { return domain_; }
    Vec3 sample(const Vec2& uv) const override {
        const double x = uv[0], y = uv[1];
        const double bump = std::exp(-((x - 0.3) * (x - 0.3) + (y - 0.65) * (y - 0.65)) / 0.004);
        const double ripple = 0.05 * std::sin(9 * x) * std::cos(7 * y);
        return Vec3(x, y, amplitude_ * (0.25 * bump + ripple));
    }
    void setAmplitude(double a) { amplitude_ = a; }

  private:
    MeshData domain_;
    double amplitude_;
};

// Applies `flips` random edge flips (where the quad is convex) to a domain: irregular vertex degrees.
inline MeshData flipRandomEdges(MeshData d, int flips, unsigned seed) {
    std::mt19937 rng(seed);
    auto ccw = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const Vec2 e1 = d.uvs[b] - d.uvs[a], e2 = d.uvs[c] - d.uvs[a];
        return e1[0] * e2[1] - e1[1] * e2[0] > 1e-9;
    };
    for (int done = 0, attempts = 0; done < flips && attempts < 100 * flips; ++attempts) {
        const std::size_t t = rng() % d.triangles.size();
        const int k = static_cast<int>(rng() % 3);
        const auto a = d.triangles[t][k], b = d.triangles[t][(k + 1) % 3], c = d.triangles[t][(k + 2) % 3];
        for (std::size_t u = 0; u < d.triangles.size(); ++u) {
            const auto& o = d.triangles[u];
            for (int j = 0; j < 3; ++j) {
                if (o[j] != b || o[(j + 1) % 3] != a) continue;
                const auto e = o[(j + 2) % 3];
                if (ccw(c, a, e) && ccw(e, b, c)) {
                    d.triangles[t] = {c, a, e};
                    d.triangles[u] = {e, b, c};
                    ++done;
                }
                j = 3;
                u = d.triangles.size();
            }
        }
    }
    return d;
}

struct NamedDomain {
    std::string name;
    MeshData domain;
};

inline std::vector<NamedDomain> testDomains() {
    return {
        {"alternating", gridDomain(4, 4, Diagonals::Alternating)},
        {"same", gridDomain(5, 3, Diagonals::Same)},
        {"random", gridDomain(5, 5, Diagonals::Random, 0.3, false, 7)},
        {"hole", gridDomain(6, 6, Diagonals::Random, 0.2, true, 3)},
        {"fan7", fanDomain(7)},
        {"flipped", flipRandomEdges(gridDomain(6, 6, Diagonals::Random, 0.3, false, 4), 40, 4)},
    };
}

} // namespace vl::test
