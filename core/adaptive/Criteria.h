#pragma once
// Refinement and simplification tests of the adaptive mesh (paper section 5.2), each with its
// thresholds in an editable parameter struct, plus a maximum depth that caps every criterion:
//  - Depth: unconditional refinement of every face to a fixed depth;
//  - Normals: refine a face when one of its edges has a dihedral angle (between the normals of the
//    faces on both sides) above a threshold, or an angle between the averaged face normals at its two
//    endpoints above a second threshold;
//  - Contour: refine a face when its surface-contour error (|p(u,v) - P_face(u,v)| sampled over the
//    face) has an average above one threshold or a maximum above another.
// Simplification (edge welds) keeps a weld only if no face it changes would need refinement.
#include "core/common/EnumNames.h"
#include "core/mesh/Mesh.h"

#include <memory>
#include <span>
#include <string_view>

namespace vl {

class AdaptiveMesh;

enum class CriterionKind { Depth, Normals, Contour };
template <> struct EnumNames<CriterionKind> {
    static constexpr const char* what = "criterion";
    static constexpr EnumName<CriterionKind> names[] = {{CriterionKind::Depth, "depth"},
                                                        {CriterionKind::Normals, "normals"},
                                                        {CriterionKind::Contour, "contour"}};
};

struct DepthCriterionParams {
    int depth = 3; // levels of edge bisection below the base mesh
    bool operator==(const DepthCriterionParams&) const = default;
};

struct NormalsCriterionParams {
    double dihedralAngleDeg = 20.0; // between the normals of the two faces of an edge
    double normalAngleDeg = 20.0;   // between the averaged face normals at the two endpoints
    bool operator==(const NormalsCriterionParams&) const = default;
};

struct ContourCriterionParams {
    double averageError = 0.02; // model units (cm for the bundled faces)
    double maximumError = 0.08; // model units
    int samplesPerSide = 4;     // quadrature: centroids of the n x n sub-triangles of each face
    bool operator==(const ContourCriterionParams&) const = default;
};

struct CriterionSettings {
    CriterionKind kind = CriterionKind::Depth;
    int maxDepth = 10; // no criterion refines a face beyond this level
    DepthCriterionParams depth;
    NormalsCriterionParams normals;
    ContourCriterionParams contour;
    bool operator==(const CriterionSettings&) const = default;
};

// Throws InputError naming the parameter for values out of range (negative thresholds, depth < 0,
// maxDepth outside [0, 30], samplesPerSide outside [1, 32]).
void validateCriterionSettings(const CriterionSettings& settings);

class Criterion {
  public:
    virtual ~Criterion() = default;
    // Faces at this level are never refined.
    virtual int maxDepth() const = 0;
    // The refinement test of one face (only asked for faces below maxDepth()).
    virtual bool needsRefinement(const AdaptiveMesh& mesh, OpenMesh::FaceHandle face) const = 0;
    // True when needsRefinement reads the neighbourhood of the face (then a change re-tests the faces
    // around the changed faces' vertices, not only the changed faces).
    virtual bool readsNeighbourhood() const { return false; }
    // The simplification test, on the faces a weld just changed (and their neighbourhood when
    // readsNeighbourhood()): keep the weld only if none of them needs refinement.
    virtual bool allowsSimplification(const AdaptiveMesh& mesh,
                                      std::span<const OpenMesh::FaceHandle> faces) const;
};

// The criterion of `settings.kind` with its thresholds (validated first).
std::unique_ptr<Criterion> makeCriterion(const CriterionSettings& settings);

// Angle in radians between two vectors (0 when either is zero); robust near 0 and pi.
double angleBetween(const Vec3& a, const Vec3& b);
// Unit normal of a face of the adaptive mesh from its sampled positions (zero when degenerate).
Vec3 faceNormal(const AdaptiveMesh& mesh, OpenMesh::FaceHandle face);
// Normalised average of the unit normals of the faces around v.
Vec3 averagedVertexNormal(const AdaptiveMesh& mesh, OpenMesh::VertexHandle v);

} // namespace vl
