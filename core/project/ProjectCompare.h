#pragma once
// Exact field-by-field comparison of the plain structs a project holds (the core modules define no
// comparison operators of their own). Doubles compare by value (NaN is never equal). Used by
// Project's operator== and by anything that needs to know whether one section changed.
#include "core/project/Project.h"

namespace vl {

bool sameMesh(const MeshData& a, const MeshData& b);
bool sameFrequencies(const FrequencySource& a, const FrequencySource& b);
bool sameField(const VectorField& a, const VectorField& b);
// A constant stage's parameter index is ignored (it has none in the file).
bool sameDeformation(const ProjectDeformation& a, const ProjectDeformation& b);
bool sameRefinement(const CriterionSettings& a, const CriterionSettings& b);
bool sameResult(const std::optional<ReductionResult>& a, const std::optional<ReductionResult>& b);

} // namespace vl
