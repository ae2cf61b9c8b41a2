#include "core/deform/CascadeAtPose.h"

#include <algorithm>
#include <cmath>

namespace vl {

namespace {

// Cells per side of the (u,v) square: the face's regions span 2-20 % of it, so a cell is about as
// large as the smallest region.
constexpr int kCells = 32;

// The cell of a box corner (any x) and of a point in [0,1] (the same cell: truncation is floor there).
int cellOf(double x) {
    return std::clamp(static_cast<int>(std::floor(x * kCells)), 0, kCells - 1);
}
inline int cellOfInside(double x) {
    return std::min(static_cast<int>(x * kCells), kCells - 1);
}

// The (u,v) box outside which the region's weight is exactly 0, padded against rounding in the
// rotated case (a rotated ellipse lies within the circle of its larger radius).
void regionBox(const InfluenceField& region, double lo[2], double hi[2]) {
    const double pad = region.rotation == 0.0 ? 0.0 : 1e-9;
    const double r[2] = {
        region.rotation == 0.0 ? region.radii[0] : std::max(region.radii[0], region.radii[1]),
        region.rotation == 0.0 ? region.radii[1] : std::max(region.radii[0], region.radii[1])};
    for (int a = 0; a < 2; ++a) {
        lo[a] = region.centre[a] - r[a] * (1 + pad) - pad;
        hi[a] = region.centre[a] + r[a] * (1 + pad) + pad;
    }
}

} // namespace

CascadeAtPose::CascadeAtPose(const DeformationCascade& cascade, std::span<const double> q)
    : q_(q.begin(), q.end()) {
    std::vector<std::vector<Term>> cells(static_cast<std::size_t>(kCells) * kCells);
    for (std::size_t s = 0; s < cascade.stages.size(); ++s) {
        const DeformationStage& stage = cascade.stages[s];
        const bool constant = stage.kind == StageKind::Constant;
        if (!constant && q_[stage.parameter] == 0.0) continue;
        // Start the stage in every cell when it has a sampled part or resets the point; else only
        // where one of its regions reaches.
        std::vector<bool> started(cells.size(), false);
        const auto start = [&](std::size_t c) {
            if (!started[c]) cells[c].push_back({static_cast<std::uint32_t>(s), -1});
            started[c] = true;
        };
        if (constant || !stage.field.sampled.empty())
            for (std::size_t c = 0; c < cells.size(); ++c) start(c);
        for (std::size_t k = 0; k < stage.field.influences.size(); ++k) {
            double lo[2], hi[2];
            regionBox(stage.field.influences[k], lo, hi);
            for (int j = cellOf(lo[1]); j <= cellOf(hi[1]); ++j)
                for (int i = cellOf(lo[0]); i <= cellOf(hi[0]); ++i) {
                    const auto c = static_cast<std::size_t>(j) * kCells + static_cast<std::size_t>(i);
                    start(c);
                    cells[c].push_back({static_cast<std::uint32_t>(s), static_cast<std::int32_t>(k)});
                }
        }
    }
    cellStart_.reserve(cells.size() + 1);
    cellStart_.push_back(0);
    for (const auto& cell : cells) {
        terms_.insert(terms_.end(), cell.begin(), cell.end());
        cellStart_.push_back(static_cast<std::uint32_t>(terms_.size()));
    }
}

Vec3 CascadeAtPose::at(const DeformationCascade& cascade, double u, double v) const {
    // Outside the square the cells would not bound the regions: the plain evaluation.
    if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return cascade.evaluateUnchecked(u, v, q_);
    const std::size_t c =
        static_cast<std::size_t>(cellOfInside(v)) * kCells + static_cast<std::size_t>(cellOfInside(u));
    Vec3 p(0.0, 0.0, 0.0), sum(0.0, 0.0, 0.0);
    const DeformationStage* stage = nullptr;
    // As evaluateUnchecked: a Constant stage sets the point, an AddVector stage adds q times its field.
    const auto finish = [&] {
        if (!stage) return;
        if (stage->kind == StageKind::Constant)
            p = sum;
        else
            p += q_[stage->parameter] * sum;
    };
    for (std::uint32_t t = cellStart_[c]; t != cellStart_[c + 1]; ++t) {
        const Term& term = terms_[t];
        if (term.region < 0) {
            finish();
            stage = &cascade.stages[term.stage];
            sum = stage->field.sampled.empty() ? Vec3(0.0, 0.0, 0.0) : stage->field.sampled.at(u, v);
        } else {
            sum += stage->field.influences[static_cast<std::size_t>(term.region)].at(u, v);
        }
    }
    finish();
    return p;
}

} // namespace vl
