#pragma once
// Which built-in individual (face::makeFaceGeometry) a cascade's base geometry is. A project stores
// a built-in base geometry by reference ({"builtin": "retarget"}, see FieldJson.h), so the
// retargeting choice is part of the project state and is read back from the cascade itself.
#include "core/deform/DeformationCascade.h"
#include "core/face/BundledFace.h"

#include <optional>

namespace vl {

// The individual whose geometry image is the sampled field of the cascade's last Constant stage (the
// one that counts), or nullopt for any other base geometry. Implemented in FieldJson.cpp, next to
// the comparison the project writer uses.
std::optional<face::Individual> builtinIndividualOf(const DeformationCascade& cascade);

} // namespace vl
