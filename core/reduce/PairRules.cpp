#include "core/reduce/PairRules.h"

#include <bit>
#include <numeric>

namespace vl {

bool PairRules::admits(UnitMask group) const {
    for (const auto& [a, b] : together)
        if ((group >> a & 1) != (group >> b & 1)) return false;
    for (const auto& [a, b] : apart)
        if ((group >> a & 1) && (group >> b & 1)) return false;
    return true;
}

UnitMask AtomModel::unitsOf(UnitMask atomGroup) const {
    UnitMask units = 0;
    for (UnitMask bits = atomGroup; bits; bits &= bits - 1)
        units |= members[static_cast<std::size_t>(std::countr_zero(bits))];
    return units;
}

UnitMask AtomModel::atomsOf(UnitMask unitGroup) const {
    UnitMask atomGroup = 0;
    for (std::size_t k = 0; k < members.size(); ++k)
        if (members[k] & unitGroup) atomGroup |= UnitMask{1} << k;
    return atomGroup;
}

AtomModel atomModel(const GroupCostModel& model, const PairRules& rules) {
    const int n = model.size();
    std::vector<int> root(static_cast<std::size_t>(n));
    std::iota(root.begin(), root.end(), 0);
    auto find = [&](int a) {
        while (root[static_cast<std::size_t>(a)] != a) a = root[static_cast<std::size_t>(a)];
        return a;
    };
    for (const auto& [a, b] : rules.together) root[static_cast<std::size_t>(find(b))] = find(a);
    AtomModel out;
    std::vector<int> atomOf(static_cast<std::size_t>(n), -1);
    for (int a = 0; a < n; ++a) {
        const int r = find(a);
        if (atomOf[static_cast<std::size_t>(r)] < 0) {
            atomOf[static_cast<std::size_t>(r)] = static_cast<int>(out.members.size());
            out.members.push_back(0);
        }
        atomOf[static_cast<std::size_t>(a)] = atomOf[static_cast<std::size_t>(r)];
        out.members[static_cast<std::size_t>(atomOf[static_cast<std::size_t>(a)])] |= UnitMask{1} << a;
    }
    const std::size_t count = out.members.size();
    GroupCostModel& atoms = out.atoms;
    atoms.weight.assign(count, 0.0);
    atoms.self.assign(count, 0.0);
    atoms.rest.assign(count, 0.0);
    atoms.cross.assign(count * count, 0.0);
    atoms.conflicts.assign(count, 0);
    atoms.scale = model.scale;
    atoms.restUnit = model.restUnit >= 0 ? atomOf[static_cast<std::size_t>(model.restUnit)] : -1;
    auto conflict = [&](int a, int b) {
        const auto i = static_cast<std::size_t>(atomOf[static_cast<std::size_t>(a)]),
                   j = static_cast<std::size_t>(atomOf[static_cast<std::size_t>(b)]);
        if (i == j) out.feasible = false;
        atoms.conflicts[i] |= UnitMask{1} << j;
        atoms.conflicts[j] |= UnitMask{1} << i;
    };
    for (int a = 0; a < n; ++a) {
        const auto i = static_cast<std::size_t>(a), k = static_cast<std::size_t>(atomOf[i]);
        atoms.weight[k] += model.weight[i];
        atoms.self[k] += model.self[i];
        if (!model.rest.empty()) atoms.rest[k] += model.rest[i];
        for (int b = 0; b < n; ++b)
            atoms.cross[k * count + static_cast<std::size_t>(atomOf[static_cast<std::size_t>(b)])] +=
                model.h(a, b);
        for (UnitMask bits = model.conflicts[i]; bits; bits &= bits - 1) conflict(a, std::countr_zero(bits));
    }
    for (const auto& [a, b] : rules.apart) conflict(a, b);
    return out;
}

} // namespace vl
