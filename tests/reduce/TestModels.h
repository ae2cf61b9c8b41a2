#pragma once
// Cost models straight from random instances, no solver in between, for the solvers' tests.
#include "RandomShapes.h"

#include "core/common/Error.h"
#include "core/reduce/GramMatrix.h"
#include "core/reduce/GroupCostModel.h"

#include <optional>
#include <span>

namespace vl::test {

// A rest-free model straight from a random instance and constraints, no solver in between: unit a of
// `units`, the rest unit that of `restViseme`, rest costs f_i sum_k w_k |a_ik - neutral_k|^2 per
// viseme. Nothing when the constraints contradict each other.
inline std::optional<GroupCostModel> restFreeModel(const RandomInstance& inst, const ReductionConstraints& c,
                                                   int restViseme, std::span<const Vec3> neutral) {
    const int n = static_cast<int>(inst.shapes.size());
    ConstraintUnits units;
    try {
        units = constraintUnits(c, n);
    } catch (const InputError&) {
        return std::nullopt;
    }
    GroupCostModel model =
        makeGroupCostModel(centredGram(inst.shapes, inst.frequencies, inst.weights), inst.frequencies, units);
    std::vector<double> restCosts;
    for (std::size_t i = 0; i < inst.shapes.size(); ++i) {
        double sum = 0;
        for (std::size_t k = 0; k < neutral.size(); ++k)
            sum += inst.weights[k] * (inst.shapes[i][k] - neutral[k]).sqrnorm();
        restCosts.push_back(inst.frequencies[i] * sum);
    }
    makeRestFree(model, restCosts, units, units.unitOf[static_cast<std::size_t>(restViseme)]);
    return model;
}

} // namespace vl::test
