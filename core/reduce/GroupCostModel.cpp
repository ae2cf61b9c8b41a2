#include "core/reduce/GroupCostModel.h"

#include <algorithm>

namespace vl {

double GroupCostModel::cost(UnitMask group) const {
    GroupSums sums;
    for (UnitMask bits = group; bits; bits &= bits - 1) {
        const int a = std::countr_zero(bits);
        double crossSum = 0;
        for (UnitMask before = group & ((UnitMask{1} << a) - 1); before; before &= before - 1)
            crossSum += h(a, std::countr_zero(before));
        sums = sums.plus(*this, a, crossSum);
    }
    return sums.cost();
}

double GroupCostModel::singletonCost(int a) const {
    return GroupSums{}.plus(*this, a, 0.0).cost();
}

bool GroupCostModel::allowed(UnitMask group) const {
    for (UnitMask bits = group; bits; bits &= bits - 1)
        if (conflicts[static_cast<std::size_t>(std::countr_zero(bits))] & group) return false;
    return true;
}

GroupCostModel makeGroupCostModel(std::span<const double> gram, std::span<const double> frequencies,
                                  const ConstraintUnits& units) {
    const std::size_t n = frequencies.size();
    const std::size_t count = units.size();
    GroupCostModel model;
    model.weight.assign(count, 0.0);
    model.self.assign(count, 0.0);
    model.cross.assign(count * count, 0.0);
    model.conflicts = units.conflicts;
    model.rest.assign(count, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const auto a = static_cast<std::size_t>(units.unitOf[i]);
        model.weight[a] += frequencies[i];
        model.self[a] += frequencies[i] * gram[i * n + i];
        for (std::size_t j = 0; j < n; ++j) {
            const auto b = static_cast<std::size_t>(units.unitOf[j]);
            model.cross[a * count + b] += frequencies[i] * frequencies[j] * gram[i * n + j];
        }
    }
    const UnitMask all = count == 64 ? ~UnitMask{0} : (UnitMask{1} << count) - 1;
    model.scale = model.cost(all);
    return model;
}

void makeRestFree(GroupCostModel& model, std::span<const double> restCosts, const ConstraintUnits& units,
                  int restUnit) {
    const std::size_t count = model.weight.size();
    if (units.size() == count + 1) { // the virtual rest unit: row and column of zeros
        std::vector<double> cross((count + 1) * (count + 1), 0.0);
        for (std::size_t a = 0; a < count; ++a)
            std::copy_n(&model.cross[a * count], count, &cross[a * (count + 1)]);
        model.cross = std::move(cross);
        model.weight.push_back(0.0);
        model.self.push_back(0.0);
    }
    model.conflicts = units.conflicts;
    model.rest.assign(model.weight.size(), 0.0);
    for (std::size_t i = 0; i < restCosts.size(); ++i)
        model.rest[static_cast<std::size_t>(units.unitOf[i])] += restCosts[i];
    model.restUnit = restUnit;
    const std::size_t all = model.weight.size();
    model.scale = model.cost(all == 64 ? ~UnitMask{0} : (UnitMask{1} << all) - 1);
}

double partitionCost(const GroupCostModel& model, std::span<const UnitMask> groups) {
    double total = 0;
    for (const UnitMask g : groups) total += model.cost(g);
    return total;
}

} // namespace vl
