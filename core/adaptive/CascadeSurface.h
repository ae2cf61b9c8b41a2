#pragma once
// The deformable face as the adaptive mesh's surface object: the face domain's coarse base
// triangulation and, as the sampling function, the deformation cascade's point at (u,v) for the
// current parameter vector. Changing the parameters and calling AdaptiveMesh::adapt re-adapts.
#include "core/adaptive/AdaptiveMesh.h"
#include "core/adaptive/Criteria.h"
#include "core/deform/CascadeAtPose.h"
#include "core/deform/DeformationCascade.h"

#include <functional>
#include <span>
#include <vector>

namespace vl {

class CascadeSurface : public Surface {
  public:
    // Validates the cascade and checks q (InputError naming the parameter).
    CascadeSurface(DeformationCascade cascade, MeshData baseDomain, std::vector<double> q);

    const MeshData& baseDomain() const override { return domain_; }
    // The cascade's point (DeformationCascade::evaluateUnchecked to the bit), through the pose's index.
    Vec3 sample(const Vec2& uv) const override { return pose_.at(cascade_, uv[0], uv[1]); }

    const DeformationCascade& cascade() const { return cascade_; }
    const std::vector<double>& parameters() const { return q_; }
    // Checks q first; the mesh must be resampled (adapt/resample) afterwards. Returns where in (u,v)
    // the surface may have changed: outside it every sample is the same to the bit (a field adds exactly
    // zero outside its influence regions), so adapt(criterion, changed) need not look there.
    UvBox setParameters(std::vector<double> q);

  private:
    DeformationCascade cascade_;
    MeshData domain_;
    std::vector<double> q_;
    CascadeAtPose pose_; // cascade_ at q_
};

// Refines `mesh` until the criterion holds under every parameter vector of `poses` (refining for each
// in turn, repeated until a whole round splits nothing), so that one (u,v) mesh serves them all: the
// viseme meshes generated on it form an interpolable set. Leaves the surface at the last pose.
// `progress` gets an estimate in [0, 1) after every pose (the number of rounds is not known ahead: the
// first round is counted as 80 %); it may throw to cancel.
AdaptStats refineForPoses(AdaptiveMesh& mesh, CascadeSurface& surface, const Criterion& criterion,
                          std::span<const std::vector<double>> poses,
                          const std::function<void(double)>& progress = {});

// One call for the tools: the face domain's base mesh (face::faceBaseDomain(baseResolution)) refined
// under `settings` for every pose. Returns the mesh with (u,v); positions are those of the last pose.
MeshData refineFaceMesh(const DeformationCascade& cascade, int baseResolution,
                        const CriterionSettings& settings, std::span<const std::vector<double>> poses,
                        AdaptStats* stats = nullptr, const std::function<void(double)>& progress = {});

} // namespace vl
