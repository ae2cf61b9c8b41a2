#include "core/face/ClosedEyes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vl::face {

namespace {

constexpr double kNone = std::numeric_limits<double>::quiet_NaN();

// The front-most depth (z) of the surface over a grid of (x, y) cells (an orthographic z-buffer along
// the face's forward axis), so that recess is measured on the surface seen from the front however the
// mesh is cut.
class FrontDepth {
  public:
    FrontDepth(std::span<const std::array<Vec3, 3>> triangles, const Vec2& lo, const Vec2& hi, double cell)
        : lo_(lo), cell_(cell), nx_(static_cast<int>((hi[0] - lo[0]) / cell) + 1),
          ny_(static_cast<int>((hi[1] - lo[1]) / cell) + 1), z_(std::size_t(nx_) * ny_, kNone) {
        for (const auto& t : triangles) {
            double x0 = t[0][0], x1 = x0, y0 = t[0][1], y1 = y0;
            for (const auto& p : t) {
                x0 = std::min(x0, p[0]);
                x1 = std::max(x1, p[0]);
                y0 = std::min(y0, p[1]);
                y1 = std::max(y1, p[1]);
            }
            const int i0 = std::max(0, static_cast<int>(std::ceil((x0 - lo_[0]) / cell_ - 0.5)));
            const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((x1 - lo_[0]) / cell_ - 0.5)));
            const int j0 = std::max(0, static_cast<int>(std::ceil((y0 - lo_[1]) / cell_ - 0.5)));
            const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((y1 - lo_[1]) / cell_ - 0.5)));
            const double area =
                (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
            if (std::abs(area) < 1e-300) continue; // seen edge-on
            for (int j = j0; j <= j1; ++j)
                for (int i = i0; i <= i1; ++i) {
                    const double x = lo_[0] + (i + 0.5) * cell_, y = lo_[1] + (j + 0.5) * cell_;
                    const double a = ((t[1][0] - x) * (t[2][1] - y) - (t[2][0] - x) * (t[1][1] - y)) / area;
                    const double b = ((t[2][0] - x) * (t[0][1] - y) - (t[0][0] - x) * (t[2][1] - y)) / area;
                    const double c = 1.0 - a - b;
                    if (a < -1e-9 || b < -1e-9 || c < -1e-9) continue;
                    const double z = a * t[0][2] + b * t[1][2] + c * t[2][2];
                    double& at = z_[std::size_t(j) * nx_ + i];
                    if (std::isnan(at) || z > at) at = z;
                }
        }
    }
    int nx() const { return nx_; }
    int ny() const { return ny_; }
    double z(int i, int j) const { return z_[std::size_t(j) * nx_ + i]; }
    Vec2 point(int i, int j) const { return Vec2(lo_[0] + (i + 0.5) * cell_, lo_[1] + (j + 0.5) * cell_); }
    // The depth at (x, y) (the nearest cell), NaN off the surface.
    double zAt(double x, double y) const {
        const int i = static_cast<int>((x - lo_[0]) / cell_), j = static_cast<int>((y - lo_[1]) / cell_);
        return i >= 0 && j >= 0 && i < nx_ && j < ny_ ? z(i, j) : kNone;
    }

    // Per cell: how far the surface lies below the mean depth of the cells within `radius` cells (box),
    // NaN off the surface and where the box is not all on it (by the face's border the mean would be
    // of its inner side only).
    std::vector<double> recess(int radius) const {
        // Integral images of the depth and of the covered cells.
        std::vector<double> sum(std::size_t(nx_ + 1) * (ny_ + 1), 0.0), count(sum.size(), 0.0);
        const auto at = [&](std::vector<double>& v, int i, int j) -> double& {
            return v[std::size_t(j) * (nx_ + 1) + i];
        };
        for (int j = 0; j < ny_; ++j)
            for (int i = 0; i < nx_; ++i) {
                const double d = z(i, j);
                at(sum, i + 1, j + 1) =
                    at(sum, i, j + 1) + at(sum, i + 1, j) - at(sum, i, j) + (std::isnan(d) ? 0 : d);
                at(count, i + 1, j + 1) =
                    at(count, i, j + 1) + at(count, i + 1, j) - at(count, i, j) + (std::isnan(d) ? 0 : 1);
            }
        std::vector<double> out(z_.size(), kNone);
        for (int j = 0; j < ny_; ++j)
            for (int i = 0; i < nx_; ++i) {
                if (std::isnan(z(i, j)) || i < radius || j < radius || i + radius >= nx_ || j + radius >= ny_)
                    continue;
                const int a = i - radius, b = i + radius + 1, c = j - radius, d = j + radius + 1;
                const double s = at(sum, b, d) - at(sum, a, d) - at(sum, b, c) + at(sum, a, c);
                const double n = at(count, b, d) - at(count, a, d) - at(count, b, c) + at(count, a, c);
                if (n < 0.97 * (b - a) * (d - c)) continue;
                out[std::size_t(j) * nx_ + i] = s / n - z(i, j);
            }
        return out;
    }

  private:
    Vec2 lo_;
    double cell_;
    int nx_, ny_;
    std::vector<double> z_;
};

} // namespace

ClosedEyes findClosedEyes(std::span<const std::array<Vec3, 3>> triangles, double mouthDepth,
                          double mouthWidth, const EyeProportions& proportions) {
    ClosedEyes out;
    const double unit = mouthDepth;
    if (!(unit > 0.0) || !(mouthWidth > 0.0)) return out;
    // The grid reaches a socket's width beyond the search window, so its recess is measured against
    // the brow, the nose's bridge and the cheek around it.
    const double cell = unit / 30.0;
    const FrontDepth depth(triangles, Vec2(-2.6 * unit, -0.6 * unit), Vec2(2.6 * unit, 2.4 * unit), cell);
    const auto recess = depth.recess(static_cast<int>(std::lround(0.45 * unit / cell)));
    // The relief of the lids over the eyeball: depth below the mean around, at the eyeball's scale.
    const auto bulge = depth.recess(static_cast<int>(std::lround(0.15 * unit / cell)));
    const auto cellsOf = [&](const std::vector<double>& v, int i, int j) {
        return v[std::size_t(j) * depth.nx() + i];
    };
    double asymmetry = 0.0;
    for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? -1.0 : 1.0;
        // The socket's height: the centroid of the cells above half the deepest recess in the window
        // beside the nose and above its tip, weighted by how much deeper they are. (Its width is not
        // telling: beside the nose's bridge every face is recessed.)
        const auto inWindow = [&](const Vec2& p) {
            const double x = sign * p[0];
            return x > 0.15 * unit && x < 1.9 * unit && p[1] > 0.25 * unit && p[1] < 2.0 * unit;
        };
        double deepest = 0.0;
        for (int j = 0; j < depth.ny(); ++j)
            for (int i = 0; i < depth.nx(); ++i) {
                const double r = cellsOf(recess, i, j);
                if (!std::isnan(r) && inWindow(depth.point(i, j))) deepest = std::max(deepest, r);
            }
        if (deepest < 0.02 * unit) return out; // no socket to speak of
        double sum = 0.0, weight = 0.0;
        for (int j = 0; j < depth.ny(); ++j)
            for (int i = 0; i < depth.nx(); ++i) {
                const double r = cellsOf(recess, i, j);
                if (std::isnan(r) || r < 0.5 * deepest || !inWindow(depth.point(i, j))) continue;
                sum += depth.point(i, j)[1] * (r - 0.5 * deepest);
                weight += r - 0.5 * deepest;
            }
        const double y = sum / weight;
        // Across: the eye's middle is the centre of symmetry of the surface along the socket's line.
        // Under closed lids the eye shows as a bulge (the eyeball) on some faces and as a dip between
        // two ridges (lids folding into the socket) on others; both are symmetric about the eye's
        // middle, while the socket's slope down from the nose is not. For each candidate middle and
        // each row of a band about the line, the surface's relief at the eyeball's scale (`bulge`)
        // within half an eye width either side, less its linear trend, is compared with its mirror
        // image: the sum of products of mirrored values, high where the relief is strong and
        // symmetric, weighted by the distance from the candidate so that the eye's whole width counts
        // more than small features near its middle. Candidates lie 0.4 to 0.85 mouth widths from the
        // face's middle (Farkas: eye centres 6.2 cm apart, the mouth 5.2 cm wide, so about 0.6); the
        // best local maximum inside that range is the middle (one at its ends is the slope of
        // something else).
        const int half = static_cast<int>(std::lround(0.24 * mouthWidth / cell));
        std::vector<double> score(static_cast<std::size_t>(depth.nx()), kNone);
        std::vector<double> row(static_cast<std::size_t>(2 * half + 1));
        for (int i = half; i + half < depth.nx(); ++i) {
            const double x = sign * depth.point(i, 0)[0];
            if (x < 0.4 * mouthWidth || x > 0.85 * mouthWidth) continue;
            double total = 0.0;
            int rows = 0;
            for (int j = 0; j < depth.ny(); ++j) {
                if (std::abs(depth.point(i, j)[1] - y) > 0.25 * unit) continue;
                bool complete = true;
                double mean = 0.0, slope = 0.0, moment = 0.0;
                for (int k = -half; k <= half && complete; ++k) {
                    const double b = cellsOf(bulge, i + k, j);
                    complete = !std::isnan(b);
                    row[static_cast<std::size_t>(k + half)] = b;
                    mean += b;
                    slope += k * b;
                    moment += double(k) * k;
                }
                if (!complete) continue;
                mean /= 2 * half + 1;
                slope /= moment;
                for (int k = 1; k <= half; ++k)
                    total += double(k) / half * (row[std::size_t(half + k)] - mean - slope * k) *
                             (row[std::size_t(half - k)] - mean + slope * k);
                ++rows;
            }
            if (rows > 0) score[static_cast<std::size_t>(i)] = total / rows;
        }
        int best = -1;
        for (int i = 1; i + 1 < depth.nx(); ++i) {
            const double a = score[std::size_t(i - 1)], b = score[std::size_t(i)],
                         c = score[std::size_t(i + 1)];
            if (std::isnan(a) || std::isnan(b) || std::isnan(c) || b < a || b < c) continue;
            if (best < 0 || b > score[std::size_t(best)]) best = i;
        }
        if (best < 0) return out; // nothing eye-like and symmetric where eyes are
        double x = depth.point(best, 0)[0];
        {
            // The maximum between cells, from the parabola through it and its neighbours.
            const double a = score[std::size_t(best - 1)], b = score[std::size_t(best)],
                         c = score[std::size_t(best + 1)], curvature = a - 2.0 * b + c;
            if (curvature < 0.0) x += 0.5 * (a - c) / curvature * cell;
        }
        out.centre[side] = Vec3(x, y, depth.zAt(x, y));
    }
    // Mirror images averaged: the eyes are symmetric about the plane x = 0.
    const double x = 0.5 * (out.centre[1][0] - out.centre[0][0]);
    const double y = 0.5 * (out.centre[0][1] + out.centre[1][1]);
    asymmetry =
        (std::abs(out.centre[0][0] + out.centre[1][0]) + std::abs(out.centre[0][1] - out.centre[1][1])) / x;
    const double distance = 2.0 * x;
    for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? -1.0 : 1.0;
        const auto corner = [&](const Vec3& offset) {
            const double cx = sign * (x + offset[0] * distance), cy = y + offset[1] * distance;
            const double cz = depth.zAt(cx, cy);
            return Vec3(cx, cy, std::isnan(cz) ? out.centre[side][2] : cz);
        };
        out.inner[side] = corner(proportions.inner);
        out.outer[side] = corner(proportions.outer);
    }
    out.found = true;
    out.confidence = 0.3 + 0.3 * std::clamp(1.0 - asymmetry / 0.3, 0.0, 1.0);
    out.method = "eye socket (its height) and the centre of symmetry of the lids along it (its middle), "
                 "corners at average proportions";
    return out;
}

} // namespace vl::face
