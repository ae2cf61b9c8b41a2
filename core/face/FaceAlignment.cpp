#include "core/face/FaceAlignment.h"

#include "core/common/Error.h"
#include "core/face/FaceDomain.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace vl::face {

namespace {

constexpr int kAngles = 720;
constexpr double kCentreU = 0.5, kCentreV = 0.45; // middle of the face: the retraction's centre

// Least-squares affine map canonical -> (u,v): returns the 2x2 linear part (columns) and offset.
struct Affine {
    Vec2 offset{0, 0}, colX{1, 0}, colY{0, 1};
    Vec2 apply(const Vec2& p) const { return offset + colX * p[0] + colY * p[1]; }
    // The canonical vector whose image is the (u,v) vector d.
    Vec2 inverseLinear(const Vec2& d) const {
        const double det = colX[0] * colY[1] - colY[0] * colX[1];
        return Vec2((colY[1] * d[0] - colY[0] * d[1]) / det, (-colX[1] * d[0] + colX[0] * d[1]) / det);
    }
    double scale() const { return std::sqrt(std::abs(colX[0] * colY[1] - colY[0] * colX[1])); }
};

Affine fitAffine(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
    // Normal equations of [x y 1] * M = target for each output coordinate.
    std::vector<double> m(9, 0.0);
    std::vector<double> bu(3, 0.0), bv(3, 0.0);
    for (std::size_t i = 0; i < from.size(); ++i) {
        const double row[3] = {from[i][0], from[i][1], 1.0};
        for (int a = 0; a < 3; ++a) {
            for (int b = 0; b < 3; ++b) m[a * 3 + b] += row[a] * row[b];
            bu[a] += row[a] * to[i][0];
            bv[a] += row[a] * to[i][1];
        }
    }
    std::vector<double> mu = m, mv = m;
    Affine a;
    if (!solveLinearSystem(mu, bu, 3) || !solveLinearSystem(mv, bv, 3))
        throwInputError("landmarks", "they do not determine an alignment (all on one line?)");
    a.colX = Vec2(bu[0], bv[0]);
    a.colY = Vec2(bu[1], bv[1]);
    a.offset = Vec2(bu[2], bv[2]);
    return a;
}

bool isLip(Landmark l) {
    return l == Landmark::UpperLipMid || l == Landmark::LowerLipMid || l == Landmark::UpperLipRight ||
           l == Landmark::UpperLipLeft || l == Landmark::LowerLipRight || l == Landmark::LowerLipLeft;
}

// Distance from c along direction d to the border of the unit square (c inside it).
double squareRadius(const Vec2& c, const Vec2& d) {
    double r = 1e9;
    for (int k = 0; k < 2; ++k) {
        if (d[k] > 1e-12) r = std::min(r, (1.0 - c[k]) / d[k]);
        if (d[k] < -1e-12) r = std::min(r, -c[k] / d[k]);
    }
    return r;
}

} // namespace

FaceAlignment::FaceAlignment(const UvMesh& mesh, const UvLocator& locator, const FaceLandmarks& landmarks) {
    for (std::size_t k = 0; k < kRequiredLandmarkCount; ++k)
        if (!landmarks.at[k].found())
            throwInputError("landmarks", "'" + std::string(toString(static_cast<Landmark>(k))) +
                                             "' is missing: the face cannot be aligned without it");
    // Step 1's lip gap: the user's gap between the lip middles in canonical units, from an affine fit
    // of the landmarks with the lips on the mouth line.
    std::vector<Vec2> from, to;
    for (std::size_t k = 0; k < kRequiredLandmarkCount; ++k) {
        const auto l = static_cast<Landmark>(k);
        Vec2 c = canonicalPosition(l);
        if (isLip(l)) c[1] = kMouthV;
        from.push_back(c);
        to.push_back(landmarks[l].uv);
    }
    const Affine affine = fitAffine(from, to);
    const Vec2 gap =
        affine.inverseLinear(landmarks[Landmark::UpperLipMid].uv - landmarks[Landmark::LowerLipMid].uv);
    closedGap_ = std::clamp(std::abs(gap[1]) / (2.0 * kMouthHalfHeight), 0.02, 1.0);

    // Control points: canonical positions after the squeeze. Lip pairs whose targets (nearly)
    // coincide (lips that touch) become one control on the mouth line: a spline forced to map two
    // close points onto one would fold.
    std::vector<Vec2> controls, targets;
    const double uvScale = affine.scale();
    const auto control = [&](Landmark l) {
        const Vec2 c = canonicalPosition(l);
        return Vec2(c[0], squeezedMouthV(c[0], c[1], closedGap_));
    };
    const std::pair<Landmark, Landmark> lipPairs[] = {{Landmark::UpperLipMid, Landmark::LowerLipMid},
                                                      {Landmark::UpperLipRight, Landmark::LowerLipRight},
                                                      {Landmark::UpperLipLeft, Landmark::LowerLipLeft}};
    std::vector<bool> used(kLandmarkCount, false);
    for (const auto& [upper, lower] : lipPairs) {
        if (!landmarks[upper].found() || !landmarks[lower].found()) continue;
        const Vec2 cu = control(upper), cl = control(lower);
        const double targetGap = (landmarks[upper].uv - landmarks[lower].uv).norm();
        if (targetGap < 0.25 * (cu - cl).norm() * uvScale) {
            controls.push_back((cu + cl) * 0.5);
            targets.push_back((landmarks[upper].uv + landmarks[lower].uv) * 0.5);
            used[static_cast<std::size_t>(upper)] = used[static_cast<std::size_t>(lower)] = true;
        }
    }
    for (const auto l : allLandmarks()) {
        if (!landmarks[l].found() || used[static_cast<std::size_t>(l)]) continue;
        // An optional lip point without its partner still constrains its own side.
        controls.push_back(control(l));
        targets.push_back(landmarks[l].uv);
    }
    try {
        spline_ = ThinPlateSpline(controls, targets);
    } catch (const InputError&) {
        throwInputError("landmarks", "they do not determine an alignment: some coincide in (u,v) (a mirrored "
                                     "UV layout, where both halves of the face share (u,v), cannot be used)");
    }
    if (std::abs(affine.colX[0] * affine.colY[1] - affine.colY[0] * affine.colX[1]) < 1e-16)
        throwInputError("landmarks", "they do not determine an alignment (left and right coincide in (u,v))");

    measureCoverage(locator);
    findBoundary();

    // Coverage of the domain before the retraction, the part the retraction moves, and folds.
    constexpr int kSamples = 129;
    std::size_t covered = 0, moved = 0;
    for (int j = 0; j < kSamples; ++j)
        for (int i = 0; i < kSamples; ++i) {
            const Vec2 d(double(i) / (kSamples - 1), double(j) / (kSamples - 1));
            const Vec2 squeezed(d[0], squeezedMouthV(d[0], d[1], closedGap_));
            covered += coverageAt(squeezed) >= 0;
            moved += (retract(squeezed) - squeezed).norm() > 1e-12;
        }
    domainCoverage_ = double(covered) / (kSamples * kSamples);
    retracted_ = double(moved) / (kSamples * kSamples);
    constexpr int kFoldSamples = 65;
    const double reference = spline_.jacobianDeterminant(Vec2(kCentreU, kCentreV));
    for (int j = 0; j < kFoldSamples; ++j)
        for (int i = 0; i < kFoldSamples; ++i) {
            const Vec2 c = canonical(Vec2(double(i) / (kFoldSamples - 1), double(j) / (kFoldSamples - 1)));
            folded_ += spline_.jacobianDeterminant(c) * reference <= 0.0;
        }
    (void)mesh;
}

void FaceAlignment::measureCoverage(const UvLocator& locator) {
    n_ = static_cast<int>(std::ceil((1.0 - 2.0 * lo_[0]) / step_)) + 1;
    const std::size_t cells = static_cast<std::size_t>(n_) * n_;
    coverage_.assign(cells, -1);
    tbb::parallel_for(tbb::blocked_range<int>(0, n_), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j != rows.end(); ++j)
            for (int i = 0; i < n_; ++i) {
                const Vec2 c = lo_ + Vec2(i * step_, j * step_);
                coverage_[static_cast<std::size_t>(j) * n_ + i] = locator.locate(spline_(c)).found ? 0 : -1;
            }
    });
    // Uncovered components that do not reach the grid's border are holes (4-connected flood fill).
    std::vector<int> label(cells, -2); // -2 unvisited
    std::deque<std::size_t> queue;
    const auto centreOf = [&](Landmark a, Landmark b) {
        return (canonicalPosition(a) + canonicalPosition(b)) * 0.5;
    };
    const Vec2 eyeRight = centreOf(Landmark::EyeOuterRight, Landmark::EyeInnerRight);
    const Vec2 eyeLeft = centreOf(Landmark::EyeOuterLeft, Landmark::EyeInnerLeft);
    for (std::size_t s = 0; s < cells; ++s) {
        if (coverage_[s] >= 0 || label[s] != -2) continue;
        std::vector<std::size_t> members;
        bool border = false;
        queue.push_back(s);
        label[s] = 0;
        while (!queue.empty()) {
            const std::size_t c = queue.front();
            queue.pop_front();
            members.push_back(c);
            const int i = static_cast<int>(c % n_), j = static_cast<int>(c / n_);
            if (i == 0 || j == 0 || i == n_ - 1 || j == n_ - 1) border = true;
            const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
            for (int k = 0; k < 4; ++k) {
                const int a = i + di[k], b = j + dj[k];
                if (a < 0 || b < 0 || a >= n_ || b >= n_) continue;
                const std::size_t nb = static_cast<std::size_t>(b) * n_ + a;
                if (coverage_[nb] >= 0 || label[nb] != -2) continue;
                label[nb] = 0;
                queue.push_back(nb);
            }
        }
        if (border) continue; // stays -1: outside the mesh
        CoverageHole hole;
        hole.cells = members.size();
        for (const auto c : members) hole.centre += lo_ + Vec2((c % n_) * step_, (c / n_) * step_);
        hole.centre /= double(members.size());
        const int id = static_cast<int>(holes_.size()) + 1;
        for (const auto c : members) coverage_[c] = id;
        holes_.push_back(hole);
    }
    for (auto& hole : holes_) hole.role = "other";
    const std::pair<Vec2, const char*> roles[] = {
        {eyeRight, "eye_right"}, {eyeLeft, "eye_left"}, {Vec2(kMouthU, kMouthV), "mouth"}};
    for (const auto& [point, role] : roles) {
        const int at = coverageAt(point);
        if (at >= 1) holes_[static_cast<std::size_t>(at - 1)].role = role;
    }
}

int FaceAlignment::coverageAt(const Vec2& c) const {
    const int i = static_cast<int>(std::lround((c[0] - lo_[0]) / step_));
    const int j = static_cast<int>(std::lround((c[1] - lo_[1]) / step_));
    if (i < 0 || j < 0 || i >= n_ || j >= n_) return -1;
    return coverage_[static_cast<std::size_t>(j) * n_ + i];
}

void FaceAlignment::findBoundary() {
    // Per direction from the face's middle, the distance at which the mesh ends (the first uncovered
    // cell), or "never" (1e9) when it reaches the domain's border first.
    std::vector<double> radius(kAngles, 1e9);
    const Vec2 centre(kCentreU, kCentreV);
    for (int a = 0; a < kAngles; ++a) {
        const double theta = 2.0 * M_PI * a / kAngles;
        const Vec2 d(std::cos(theta), std::sin(theta));
        const double limit = squareRadius(centre, d) + 2 * step_;
        for (double r = 0.0; r <= limit; r += 0.5 * step_)
            if (coverageAt(centre + d * r) < 0) {
                radius[a] = r;
                break;
            }
    }
    // Conservative (the smallest radius within +-2 degrees) so the retraction never reaches past the
    // mesh between two sampled directions.
    boundary_.assign(kAngles, 1e9);
    for (int a = 0; a < kAngles; ++a)
        for (int k = -4; k <= 4; ++k)
            boundary_[a] = std::min(boundary_[a], radius[(a + k + kAngles) % kAngles]);
}

Vec2 FaceAlignment::retract(const Vec2& p) const {
    const Vec2 centre(kCentreU, kCentreV);
    const Vec2 d = p - centre;
    const double r = d.norm();
    if (r < 1e-12) return p;
    const double theta = std::atan2(d[1], d[0]);
    const double x = (theta < 0 ? theta + 2 * M_PI : theta) / (2 * M_PI) * kAngles;
    const int a0 = static_cast<int>(x) % kAngles, a1 = (a0 + 1) % kAngles;
    const double f = x - std::floor(x);
    const double b0 = boundary_[a0], b1 = boundary_[a1];
    if (b0 >= 1e8 && b1 >= 1e8) return p;
    const Vec2 dir = d / r;
    const double outer = squareRadius(centre, dir);
    // Directions where the mesh reaches past the border on one side only: treat as reaching just
    // past the border (a smooth transition into the identity).
    const double rc = std::min(b0 >= 1e8 ? outer * 1.05 : b0, outer * 1.05) * (1 - f) +
                      std::min(b1 >= 1e8 ? outer * 1.05 : b1, outer * 1.05) * f;
    const double target = rc - 1.5 * step_; // stay a little inside the covered area
    if (target >= outer) return p;
    const double core = 0.85 * target;
    if (r <= core) return p;
    const double mapped = core + (r - core) * (target - core) / std::max(outer - core, 1e-12);
    return centre + dir * mapped;
}

Vec2 FaceAlignment::canonical(const Vec2& domain) const {
    return retract(Vec2(domain[0], squeezedMouthV(domain[0], domain[1], closedGap_)));
}

} // namespace vl::face
