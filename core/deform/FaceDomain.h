#pragma once
// The (u,v) domain of the bundled faces: the whole unit square (its border wraps round to the sides,
// the top of the forehead and under the chin) with one hole, the mouth opening between the lips.
// The hole is a rhombus with corners at the mouth corners and at the middle of each lip, so its
// boundary is made of straight (u,v) segments: an edge split at a midpoint stays on the boundary at
// every refinement level. The base geometry squeezes the rim to an almost closed slit, and the jaw
// field opens it. Landmarks are the same for every individual (normalised (u,v) space).
#include "core/mesh/Mesh.h"

namespace vl::face {

constexpr double kMouthU = 0.5;           // mouth centre
constexpr double kMouthV = 0.3;           // mouth line (stomion)
constexpr double kMouthHalfWidth = 0.1;   // corners at kMouthU -/+ this
constexpr double kMouthHalfHeight = 0.02; // lip middles at kMouthV -/+ this (in (u,v), before squeezing)
// The other landmarks of the domain (core/face aligns a user's mesh to them): eye corners (the
// outer corner a little higher, as in most faces) and the nose tip.
constexpr double kEyeInnerU = 0.078; // inner eye corners at kMouthU -/+ this
constexpr double kEyeInnerV = 0.583;
constexpr double kEyeOuterU = 0.21; // outer eye corners at kMouthU -/+ this
constexpr double kEyeOuterV = 0.592;
constexpr double kNoseTipV = 0.415; // the nose tip at (kMouthU, kNoseTipV)

// Half-height of the hole at u (0 beyond the corners).
double mouthHoleHalfHeight(double u);
// True when (u,v) lies strictly inside the mouth hole.
bool insideMouthHole(double u, double v);

// Pulls the lips' rim together (the base geometry of every face samples its surface at the squeezed
// (u,v)): points on the rim of the hole map to within closedGap * half-height of the mouth line,
// points inside the hole scale towards it, and the shift fades out with distance from the rim.
double squeezedMouthV(double u, double v, double closedGap);
constexpr double kBundledClosedGap = 0.07; // the bundled faces' lips almost touch

enum class DomainDensity {
    Uniform,      // cells of about 1/resolution everywhere
    MouthFocused, // the same number of grid lines, gathered around the mouth and eyes
};

// A triangulated grid of the domain with the mouth hole as a boundary loop: about resolution x
// resolution cells (grid lines through the mouth centre, corners and mouth line), each cell two
// triangles with alternating diagonals (a union of basic blocks, mirror-symmetric about u = 0.5).
// positions are (u, v, 0); uvs are set. Throws InputError for resolution < 10.
MeshData faceDomainMesh(int resolution, DomainDensity density = DomainDensity::Uniform);

// The coarse base mesh of the adaptive face: faceDomainMesh(resolution, Uniform), similar-sized
// triangles; resolution 10 is the coarsest (mouth corners and lip middles are its vertices).
MeshData faceBaseDomain(int resolution = 10);

} // namespace vl::face
