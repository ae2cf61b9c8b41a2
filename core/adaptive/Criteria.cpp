#include "core/adaptive/Criteria.h"

#include "core/adaptive/AdaptiveMesh.h"
#include "core/adaptive/ContourError.h"
#include "core/common/Error.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

namespace vl {
namespace {

double radians(double degrees) {
    return degrees * std::numbers::pi / 180.0;
}

class DepthCriterion final : public Criterion {
  public:
    DepthCriterion(int depth, int maxDepth) : depth_(std::min(depth, maxDepth)) {}
    int maxDepth() const override { return depth_; }
    bool needsRefinement(const AdaptiveMesh& mesh, OpenMesh::FaceHandle f) const override {
        return mesh.level(f) < depth_;
    }

  private:
    int depth_;
};

class NormalsCriterion final : public Criterion {
  public:
    NormalsCriterion(const NormalsCriterionParams& p, int maxDepth)
        : dihedral_(radians(p.dihedralAngleDeg)), endpoint_(radians(p.normalAngleDeg)), maxDepth_(maxDepth) {}
    int maxDepth() const override { return maxDepth_; }
    bool readsNeighbourhood() const override { return true; }
    bool needsRefinement(const AdaptiveMesh& mesh, OpenMesh::FaceHandle f) const override {
        const auto& m = mesh.mesh();
        const Vec3 n = faceNormal(mesh, f);
        std::array<Vec3, 3> vertexNormal; // at the start of each halfedge, computed once
        int k = 0;
        for (const auto h : m.fh_range(f)) {
            const auto g = m.face_handle(m.opposite_halfedge_handle(h));
            if (g.is_valid() && angleBetween(n, faceNormal(mesh, g)) > dihedral_) return true;
            vertexNormal[k++] = averagedVertexNormal(mesh, m.from_vertex_handle(h));
        }
        for (int e = 0; e < 3; ++e)
            if (angleBetween(vertexNormal[e], vertexNormal[(e + 1) % 3]) > endpoint_) return true;
        return false;
    }

  private:
    double dihedral_, endpoint_;
    int maxDepth_;
};

class ContourCriterion final : public Criterion {
  public:
    ContourCriterion(const ContourCriterionParams& p, int maxDepth)
        : params_(p), pattern_(contourSamplePattern(p.samplesPerSide)), maxDepth_(maxDepth) {}
    int maxDepth() const override { return maxDepth_; }
    bool needsRefinement(const AdaptiveMesh& mesh, OpenMesh::FaceHandle f) const override {
        std::array<Vec2, 3> uv;
        std::array<Vec3, 3> p;
        int k = 0;
        for (const auto v : mesh.mesh().fv_range(f)) {
            uv[k] = mesh.uv(v);
            p[k++] = mesh.position(v);
        }
        return triangleContourErrorExceeds(mesh.surface(), uv, p, pattern_, params_.averageError,
                                           params_.maximumError);
    }

  private:
    ContourCriterionParams params_;
    std::vector<Vec3> pattern_;
    int maxDepth_;
};

void requireNonNegative(double value, std::string_view name) {
    if (!(std::isfinite(value) && value >= 0.0))
        throwInputError(name, "must be a finite number >= 0, got " + std::to_string(value));
}

} // namespace

bool Criterion::allowsSimplification(const AdaptiveMesh& mesh,
                                     std::span<const OpenMesh::FaceHandle> faces) const {
    for (const auto f : faces)
        if (mesh.level(f) < maxDepth() && needsRefinement(mesh, f)) return false;
    return true;
}

void validateCriterionSettings(const CriterionSettings& s) {
    if (s.maxDepth < 0 || s.maxDepth > 30) throwInputError("maxDepth", "must be in [0, 30]");
    if (s.depth.depth < 0) throwInputError("depth", "must be >= 0");
    requireNonNegative(s.normals.dihedralAngleDeg, "dihedralAngleDeg");
    requireNonNegative(s.normals.normalAngleDeg, "normalAngleDeg");
    requireNonNegative(s.contour.averageError, "averageError");
    requireNonNegative(s.contour.maximumError, "maximumError");
    if (s.contour.samplesPerSide < 1 || s.contour.samplesPerSide > 32)
        throwInputError("samplesPerSide", "must be in [1, 32]");
}

std::unique_ptr<Criterion> makeCriterion(const CriterionSettings& s) {
    validateCriterionSettings(s);
    switch (s.kind) {
    case CriterionKind::Depth:
        return std::make_unique<DepthCriterion>(s.depth.depth, s.maxDepth);
    case CriterionKind::Normals:
        return std::make_unique<NormalsCriterion>(s.normals, s.maxDepth);
    case CriterionKind::Contour:
        return std::make_unique<ContourCriterion>(s.contour, s.maxDepth);
    }
    throw std::logic_error("unknown criterion kind");
}

double angleBetween(const Vec3& a, const Vec3& b) {
    const double s = OpenMesh::cross(a, b).norm(), c = OpenMesh::dot(a, b);
    if (s == 0.0 && c == 0.0) return 0.0;
    return std::atan2(s, c);
}

Vec3 faceNormal(const AdaptiveMesh& mesh, OpenMesh::FaceHandle f) {
    const auto& m = mesh.mesh();
    auto h = m.halfedge_handle(f);
    const Vec3& a = m.point(m.from_vertex_handle(h));
    const Vec3& b = m.point(m.to_vertex_handle(h));
    const Vec3& c = m.point(m.to_vertex_handle(m.next_halfedge_handle(h)));
    Vec3 n = OpenMesh::cross(b - a, c - a);
    const double len = n.norm();
    return len > 0 ? n / len : Vec3(0, 0, 0);
}

Vec3 averagedVertexNormal(const AdaptiveMesh& mesh, OpenMesh::VertexHandle v) {
    Vec3 sum(0, 0, 0);
    for (const auto f : mesh.mesh().vf_range(v)) sum += faceNormal(mesh, f);
    const double len = sum.norm();
    return len > 0 ? sum / len : sum;
}

} // namespace vl
