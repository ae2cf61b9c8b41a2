#pragma once
// A cascade of deformation fields (paper section 3.3, equations 2-4): a point of the model at (u,v)
// under the parameter vector q is
//   p^0 = V^0(u,v)                      (Constant stage: the base geometry, a geometry image)
//   p^k = p^{k-1} + q_{s(k)} * V^k(u,v) (AddVector stage k, driven by parameter s(k))
// Stages run in order; a Constant stage replaces the point, so only the last one matters. The
// cascade is plain editable data: the project file saves it, the editor changes it in place.
// Retargeting to another individual replaces the Constant stage's field and keeps the rest.
#include "core/deform/VectorField.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct DeformParameter {
    std::string name; // unique, non-empty
    double min = 0.0;
    double max = 1.0;
    double defaultValue = 0.0; // in [min, max]
    bool operator==(const DeformParameter&) const = default;
};

enum class StageKind { Constant, AddVector };

struct DeformationStage {
    StageKind kind = StageKind::AddVector;
    std::string name;          // what the field models, e.g. "jaw_open" (for display and files)
    std::size_t parameter = 0; // index into DeformationCascade::parameters (AddVector only)
    VectorField field;
    bool operator==(const DeformationStage&) const = default;
};

struct DeformationCascade {
    std::string name;
    std::vector<DeformParameter> parameters;
    std::vector<DeformationStage> stages; // the first one is Constant

    // Index of the parameter with this name, or -1.
    int findParameter(std::string_view parameterName) const;
    // The default value of every parameter, in order.
    std::vector<double> defaults() const;
    // Point at (u,v) for the parameter vector q (one value per parameter). This is the obvious
    // per-point evaluation: the reference for CascadeSampler and the sampling function of the
    // adaptive mesh. Throws InputError when q has the wrong size or a value is out of range.
    Vec3 evaluate(double u, double v, std::span<const double> q) const;
    // The same without checking q (the caller has run checkParameterValues once).
    Vec3 evaluateUnchecked(double u, double v, std::span<const double> q) const;
    bool operator==(const DeformationCascade&) const = default;
};

// Throws InputError naming the cascade and the offending parameter or stage: empty or duplicate
// names, min > max, default outside the range, first stage not Constant, parameter index out of
// range, invalid fields.
void validateCascade(const DeformationCascade& cascade);

// Throws InputError "parameter 'jaw_open': value 1.5 is outside [0, 1]" (or a size mismatch).
void checkParameterValues(const DeformationCascade& cascade, std::span<const double> q);

// A copy of `cascade` whose Constant stages use `base` instead (the paper's retargeting: the same
// deformation fields on another individual's geometry in the same normalised (u,v) space).
DeformationCascade retarget(const DeformationCascade& cascade, const VectorField& base, std::string name);

} // namespace vl
