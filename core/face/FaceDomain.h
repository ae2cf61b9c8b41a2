#pragma once
// The (u,v) domain of the bundled faces: the whole unit square (its border wraps round to the sides,
// the top of the forehead and under the chin) with one hole, the mouth opening between the lips.
// The hole is a flat hexagon: straight top and bottom edges (the lips' rims over most of the mouth's
// width) that slant to the mouth corners near them. Its boundary is made of straight (u,v) segments,
// so an edge split at a midpoint stays on the boundary at every refinement level; the long flat
// rims let fields that are level along them open the lips in a rounded U rather than a V. The base geometry
// squeezes the rim to an almost closed slit, and the jaw field opens it. Landmarks are the same for every
// individual (normalised (u,v) space).
#include "core/mesh/Mesh.h"

#include <cmath>

namespace vl::face {

constexpr double kMouthU = 0.5;           // mouth centre
constexpr double kMouthV = 0.3;           // mouth line (stomion)
constexpr double kMouthHalfWidth = 0.1;   // corners at kMouthU -/+ this
constexpr double kMouthHalfHeight = 0.02; // lip middles at kMouthV -/+ this (in (u,v), before squeezing)
constexpr double kMouthFlat = 0.7;        // the rims are flat within this fraction of the half-width
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

// The head's other parts (eyeballs, teeth, tongue, mouth cavity; core/face/HeadParts.h) carry (u,v)
// in tiles to the right of the face domain, so one (u,v) per vertex still tells the parts apart and
// colours them: tile k covers u in [k, k + 1), v in [0, 1].
enum class HeadTile { Skin = 0, Eye = 1, Teeth = 2, Tongue = 3, Cavity = 4 };
constexpr int kHeadTileCount = 5;
inline HeadTile headTileOf(double u) {
    const int k = static_cast<int>(std::floor(u));
    return k >= 1 && k < kHeadTileCount ? static_cast<HeadTile>(k) : HeadTile::Skin;
}

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
