#include "core/face/ThinPlateSpline.h"

#include "core/common/Error.h"

#include <cmath>

namespace vl::face {

namespace {

double kernel(double r2) {
    return r2 > 0.0 ? 0.5 * r2 * std::log(r2) : 0.0; // r^2 log r = r^2 log(r^2) / 2
}

} // namespace

bool solveLinearSystem(std::vector<double>& m, std::vector<double>& b, std::size_t n) {
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < n; ++r)
            if (std::abs(m[r * n + col]) > std::abs(m[pivot * n + col])) pivot = r;
        if (std::abs(m[pivot * n + col]) < 1e-300) return false;
        if (pivot != col) {
            for (std::size_t c = 0; c < n; ++c) std::swap(m[col * n + c], m[pivot * n + c]);
            std::swap(b[col], b[pivot]);
        }
        for (std::size_t r = col + 1; r < n; ++r) {
            const double f = m[r * n + col] / m[col * n + col];
            if (f == 0.0) continue;
            for (std::size_t c = col; c < n; ++c) m[r * n + c] -= f * m[col * n + c];
            b[r] -= f * b[col];
        }
    }
    for (std::size_t r = n; r-- > 0;) {
        double s = b[r];
        for (std::size_t c = r + 1; c < n; ++c) s -= m[r * n + c] * b[c];
        b[r] = s / m[r * n + r];
    }
    return true;
}

ThinPlateSpline::ThinPlateSpline(std::span<const Vec2> controls, std::span<const Vec2> targets) {
    const std::size_t n = controls.size();
    if (n < 3 || targets.size() != n)
        throwInputError("thin-plate spline", "needs at least 3 control points with one target each");
    // The side conditions make the system singular for collinear control points: check first, with
    // a tolerance relative to the spread of the points.
    Vec2 mean(0, 0);
    for (const auto& c : controls) mean += c / double(n);
    double sxx = 0, sxy = 0, syy = 0;
    for (const auto& c : controls) {
        const Vec2 d = c - mean;
        sxx += d[0] * d[0];
        sxy += d[0] * d[1];
        syy += d[1] * d[1];
    }
    const double trace = sxx + syy, det = sxx * syy - sxy * sxy;
    if (trace <= 0.0 || det <= 1e-10 * trace * trace)
        throwInputError("thin-plate spline", "the control points are collinear or coincident");

    controls_.assign(controls.begin(), controls.end());
    const std::size_t size = n + 3;
    std::vector<double> m(size * size, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = 0; j < n; ++j) m[i * size + j] = kernel((controls[i] - controls[j]).sqrnorm());
        const double row[3] = {1.0, controls[i][0], controls[i][1]};
        for (int k = 0; k < 3; ++k) {
            m[i * size + n + k] = row[k];
            m[(n + k) * size + i] = row[k];
        }
    }
    weights_.assign(n, Vec2(0, 0));
    for (int dim = 0; dim < 2; ++dim) {
        std::vector<double> a = m;
        std::vector<double> b(size, 0.0);
        for (std::size_t i = 0; i < n; ++i) b[i] = targets[i][dim];
        if (!solveLinearSystem(a, b, size))
            throwInputError("thin-plate spline",
                            "the control points do not determine a map (coincident points?)");
        for (std::size_t i = 0; i < n; ++i) weights_[i][dim] = b[i];
        offset_[dim] = b[n];
        linearX_[dim] = b[n + 1];
        linearY_[dim] = b[n + 2];
    }
}

Vec2 ThinPlateSpline::affine(const Vec2& x) const {
    return offset_ + linearX_ * x[0] + linearY_ * x[1];
}

Vec2 ThinPlateSpline::operator()(const Vec2& x) const {
    Vec2 f = affine(x);
    for (std::size_t i = 0; i < controls_.size(); ++i)
        f += weights_[i] * kernel((x - controls_[i]).sqrnorm());
    return f;
}

double ThinPlateSpline::jacobianDeterminant(const Vec2& x, double h) const {
    const Vec2 dx = ((*this)(x + Vec2(h, 0)) - (*this)(x - Vec2(h, 0))) / (2 * h);
    const Vec2 dy = ((*this)(x + Vec2(0, h)) - (*this)(x - Vec2(0, h))) / (2 * h);
    return dx[0] * dy[1] - dx[1] * dy[0];
}

} // namespace vl::face
