#pragma once
// Designer constraints on a reduction (issue 14): pin a viseme as its own key (a group of one), keep
// two visemes apart (cannot-link), keep two together (must-link). Every solver honours them exactly:
// must-linked visemes are contracted into one unit before solving, and pins and apart pairs become
// conflicts between units that no group may contain together.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vl {

// By viseme index (into the problem's shapes).
struct ReductionConstraints {
    std::vector<int> pinned;                   // each is the only member of its group
    std::vector<std::pair<int, int>> apart;    // never in the same group
    std::vector<std::pair<int, int>> together; // always in the same group

    bool empty() const { return pinned.empty() && apart.empty() && together.empty(); }
};

// The same constraints by viseme name, as the CLI flags and the project file give them.
struct ConstraintNames {
    std::vector<std::string> pinned;
    std::vector<std::pair<std::string, std::string>> apart;
    std::vector<std::pair<std::string, std::string>> together;

    bool empty() const { return pinned.empty() && apart.empty() && together.empty(); }
    bool operator==(const ConstraintNames&) const = default;
};

// Indices of the named visemes; throws InputError at `where` naming an unknown viseme (with the
// known names) or a pair that names the same viseme twice.
ReductionConstraints resolveConstraints(const ConstraintNames& names,
                                        std::span<const std::string> visemeNames,
                                        std::string_view where = "constraints");

// The constraints appended one after the other (duplicates are harmless).
ConstraintNames combineConstraints(const ConstraintNames& a, const ConstraintNames& b);

// Units after contracting the must-links: unitOf[i] for every viseme, members per unit (ascending,
// units ordered by their first member) and, per unit, a bit mask of the units it may not share a
// group with. Units are at most 64 (so masks fit one word); more visemes than that are refused.
struct ConstraintUnits {
    std::vector<int> unitOf;
    std::vector<std::vector<int>> members;
    std::vector<std::uint64_t> conflicts;
    // Smallest and largest number of groups the constraints allow (minGroups > maxGroups: none).
    int minGroups = 1;
    int maxGroups = 1;

    std::size_t size() const { return members.size(); }
    bool feasible(int groups) const { return groups >= minGroups && groups <= maxGroups; }
};

// Throws InputError at `where` for indices outside 0..n-1, a viseme pinned while kept together with
// another, and a pair kept both together and apart (directly or through a chain of "together"),
// naming the visemes by `visemeNames` (or by index when that is empty).
ConstraintUnits constraintUnits(const ReductionConstraints& constraints, int n,
                                std::span<const std::string> visemeNames = {},
                                std::string_view where = "constraints");

// The InputError for a number of groups the constraints do not allow, explaining why.
[[noreturn]] void throwInfeasibleTarget(const ConstraintUnits& units, int groups, std::string_view where);

} // namespace vl
