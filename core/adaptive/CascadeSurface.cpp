#include "core/adaptive/CascadeSurface.h"

#include "core/common/Error.h"
#include "core/deform/FaceDomain.h"

#include <algorithm>

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
                          std::span<const std::vector<double>> poses) {
    if (poses.empty()) throwInputError("refinement", "no parameter vector to refine for");
    AdaptStats total;
    while (true) {
        std::size_t roundSplits = 0;
        for (const auto& q : poses) {
            surface.setParameters(q);
            mesh.resample();
            const AdaptStats s = mesh.refine(criterion);
            roundSplits += s.splits;
            total.tests += s.tests;
        }
        total.splits += roundSplits;
        // One pose alone needs no second round: refine() already reached its fixpoint.
        if (roundSplits == 0 || poses.size() == 1) break;
    }
    return total;
}

MeshData refineFaceMesh(const DeformationCascade& cascade, int baseResolution,
                        const CriterionSettings& settings, std::span<const std::vector<double>> poses,
                        AdaptStats* stats) {
    const auto criterion = makeCriterion(settings);
    if (poses.empty()) throwInputError("refinement", "no parameter vector to refine for");
    CascadeSurface surface(cascade, face::faceBaseDomain(baseResolution), poses.front());
    AdaptiveMesh mesh(surface);
    const AdaptStats s = refineForPoses(mesh, surface, *criterion, poses);
    if (stats) *stats = s;
    return mesh.toMeshData();
}

} // namespace vl
