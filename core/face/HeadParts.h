#pragma once
// The head's other parts: eyeballs, upper and lower teeth, tongue and the mouth cavity, as separate
// meshes that the face's deformation fields carry. Each part vertex is attached to an anchor (u,v) of
// the face domain and follows a fraction of the displacement the cascade's fields give there,
// per parameter: the lower teeth and the tongue follow the jaw (jaw_open at the chin, the mandible),
// the upper teeth and the eyeballs follow nothing (the skull), the cavity's rim follows the lips'
// rim exactly and its depths blend into the jaw (floor: the mandible as the lower teeth follow it, not
// the lower lip, which the modioli hold back near the corners) or the skull (roof). Parameters that act on
// a part alone (the tongue's tongue_up and tongue_out) add their own per-vertex displacements.
//
// Parts are derived from the cascade, not stored: the bundled head's parts, carried to another face
// by the similarity between its landmarks and the bundled face's (eyes to each eye, teeth and tongue
// to the mouth), the cavity built on the face's own lip rim. Their (u,v) lie in tiles beside the face
// domain (face::HeadTile), so preview colours and exports tell the parts apart.
#include "core/deform/DeformationCascade.h"
#include "core/deform/Visemes.h"
#include "core/face/Landmarks.h"
#include "core/mesh/VisemeSet.h"

#include <array>
#include <span>
#include <string>
#include <vector>

namespace vl::face {

struct HeadPart {
    std::string name;          // eye_right, eye_left, teeth_upper, teeth_lower, tongue, mouth_cavity
    MeshData rest;             // positions at the default parameters, triangles, (u,v) in the part's tile
    std::vector<Vec2> anchors; // per vertex: the face-domain (u,v) whose field displacement it follows
    struct Follow {
        int parameter = -1;         // cascade parameter index, or -1 for every parameter
        std::vector<double> weight; // per vertex
        std::vector<Vec2> anchors;  // per vertex where this follow samples the fields; empty: `anchors`
    };
    std::vector<Follow> follows;
    struct Own {
        int parameter = 0;
        std::vector<Vec3> displacement; // per vertex, per unit of the parameter
    };
    std::vector<Own> own;
};

// The parts of the head whose face is `cascade` (see the header comment). Parameters the cascade does
// not have are simply not followed.
std::vector<HeadPart> makeHeadParts(const DeformationCascade& cascade);

// The parts' vertices, all parts in order, for the parameter vector q (checked like
// checkParameterValues): rest + sum_k q_k * D_k with D_k sampled once.
class HeadPartsSampler {
  public:
    HeadPartsSampler(const DeformationCascade& cascade, std::span<const HeadPart> parts);
    std::size_t vertexCount() const { return rest_.size(); }
    std::vector<Vec3> evaluate(std::span<const double> q) const;
    // The linear form of evaluate(): the positions at q = 0 and D_k, the displacement per unit of
    // parameter k (all zero for a parameter no part follows), so that a morph shader reproduces any
    // q as rest + sum_k q_k D_k.
    const std::vector<Vec3>& rest() const { return rest_; }
    std::vector<Vec3> displacement(std::size_t parameter) const;

  private:
    DeformationCascade ranges_; // parameter names and ranges only
    std::vector<Vec3> rest_;
    std::vector<std::vector<Vec3>> displacement_; // per parameter, per vertex (empty when unused)
};

// Where makeHeadParts puts the eyeball of a face whose base geometry has these landmark positions
// (baseLandmarkPositions): the bundled eyeball carried to the eye (`left`: the face's left eye).
Vec3 carriedEyeballCentre(const std::array<Vec3, kLandmarkCount>& landmarks, bool left);

// The parts as one mesh (vertices of each part in order, triangles re-indexed) at rest.
MeshData partsMesh(std::span<const HeadPart> parts);

// The viseme set of the whole head: the skin on `uvMesh` (as generateVisemeSet) followed by the
// parts' vertices, in a fixed order, so the set stays interpolable.
VisemeSet generateHeadVisemeSet(const DeformationCascade& cascade, const MeshData& uvMesh,
                                std::span<const VisemeParameters> visemes, std::span<const HeadPart> parts);

} // namespace vl::face
