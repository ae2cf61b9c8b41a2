#pragma once
// Visemes as parameter vectors of a deformation cascade. Generating every viseme on one (u,v) mesh
// gives meshes that share vertex order and triangles: an interpolable set by construction, ready for
// the reduction (core/reduce).
#include "core/deform/DeformationCascade.h"
#include "core/mesh/VisemeSet.h"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace vl {

// A named parameter vector: parameters not listed keep their default value.
struct VisemeParameters {
    std::string name;
    std::vector<std::pair<std::string, double>> values; // (parameter name, value)
    bool operator==(const VisemeParameters&) const = default;
};

// The 15 Oculus/Meta visemes (sil, PP, FF, TH, DD, kk, CH, SS, nn, RR, aa, E, ih, oh, ou) for the
// parameters of face::makeFaceCascade.
std::vector<VisemeParameters> oculusVisemes();

// Defaults overridden by `viseme.values`; throws InputError naming the viseme and parameter for an
// unknown name, a repeated name or a value outside the parameter's range.
std::vector<double> parameterVector(const DeformationCascade& cascade, const VisemeParameters& viseme);

// The neutral mesh (default parameters) and one mesh per viseme on the triangles and (u,v) of
// `uvMesh` (its positions are ignored). Throws InputError for a mesh without (u,v), fewer than two
// visemes, or empty / duplicate viseme names.
VisemeSet generateVisemeSet(const DeformationCascade& cascade, const MeshData& uvMesh,
                            std::span<const VisemeParameters> visemes);

} // namespace vl
