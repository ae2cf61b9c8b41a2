#include "core/adaptive/CascadeSurface.h"

#include "core/common/Error.h"
#include "core/face/FaceDomain.h"

#include <algorithm>
#include <cmath>

namespace vl {

CascadeSurface::CascadeSurface(DeformationCascade cascade, MeshData baseDomain, std::vector<double> q)
    : cascade_(std::move(cascade)), domain_(std::move(baseDomain)) {
    validateCascade(cascade_);
    setParameters(std::move(q));
}

namespace {

// Where a field can be non-zero: everywhere for a sampled field, else its regions' boxes (a rotated
// ellipse lies within the circle of its larger radius).
UvBox fieldSupport(const VectorField& field) {
    if (!field.sampled.samples.empty()) return UvBox::everywhere();
    UvBox box;
    for (const auto& region : field.influences) {
        const Vec2 r =
            region.rotation == 0.0 ? region.radii : Vec2(1, 1) * std::max(region.radii[0], region.radii[1]);
        box.include({region.centre - r, region.centre + r});
    }
    return box;
}

} // namespace

UvBox CascadeSurface::setParameters(std::vector<double> q) {
    checkParameterValues(cascade_, q);
    UvBox changed;
    if (q_.size() != q.size()) {
        changed = UvBox::everywhere();
    } else {
        for (const auto& stage : cascade_.stages)
            if (stage.kind == StageKind::AddVector && q_[stage.parameter] != q[stage.parameter])
                changed.include(fieldSupport(stage.field));
    }
    q_ = std::move(q);
    pose_ = CascadeAtPose(cascade_, q_);
    return changed;
}

AdaptStats refineForPoses(AdaptiveMesh& mesh, CascadeSurface& surface, const Criterion& criterion,
                          std::span<const std::vector<double>> poses,
                          const std::function<void(double)>& progress) {
    if (poses.empty()) throwInputError("refinement", "no parameter vector to refine for");
    AdaptStats total;
    for (int round = 0;; ++round) {
        std::size_t roundSplits = 0;
        for (std::size_t i = 0; i < poses.size(); ++i) {
            surface.setParameters(poses[i]);
            mesh.resample();
            const AdaptStats s = mesh.refine(criterion);
            roundSplits += s.splits;
            total.tests += s.tests;
            // Later rounds split little: each takes a fifth of the time left.
            const double inRound = static_cast<double>(i + 1) / static_cast<double>(poses.size());
            if (progress)
                progress(round == 0 ? 0.8 * inRound
                                    : 1.0 - 0.2 * std::pow(0.2, round - 1) * (1.0 - 0.8 * inRound));
        }
        total.splits += roundSplits;
        // One pose alone needs no second round: refine() already reached its fixpoint.
        if (roundSplits == 0 || poses.size() == 1) break;
    }
    return total;
}

MeshData refineFaceMesh(const DeformationCascade& cascade, int baseResolution,
                        const CriterionSettings& settings, std::span<const std::vector<double>> poses,
                        AdaptStats* stats, const std::function<void(double)>& progress) {
    const auto criterion = makeCriterion(settings);
    if (poses.empty()) throwInputError("refinement", "no parameter vector to refine for");
    CascadeSurface surface(cascade, face::faceBaseDomain(baseResolution), poses.front());
    AdaptiveMesh mesh(surface);
    const AdaptStats s = refineForPoses(mesh, surface, *criterion, poses, progress);
    if (stats) *stats = s;
    return mesh.toMeshData();
}

} // namespace vl
