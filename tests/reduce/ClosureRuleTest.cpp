// The lips-closed viseme keeps a key of its own when the rest is free (ReduceSettings::closure): on a
// set where the optimum without the rule rests PP (a small motion, rarely used), the rule pins it and
// the run is the optimum under that pin; the designer's own constraints, the keyed model and a target
// the pin would rule out leave it to the optimiser, each saying why.
#include "core/common/Error.h"
#include "core/reduce/Frequencies.h"
#include "core/reduce/ReduceRun.h"
#include "tests/export/TestModels.h"
#include "tests/reduce/InputErrorText.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

// sil (no motion), PP (small motion, low frequency) and three vowels far apart and frequent.
VisemeSet closureSet() {
    VisemeSet set;
    set.neutral = test::gridMesh(3, 3, true);
    const std::pair<const char*, Vec3> visemes[] = {{"sil", Vec3(0, 0, 0)},
                                                    {"PP", Vec3(0, 0.2, 0)},
                                                    {"aa", Vec3(0, -4, 0)},
                                                    {"E", Vec3(3, -1, 0)},
                                                    {"O", Vec3(-3, -2, 1)}};
    for (const auto& [name, offset] : visemes) {
        Viseme viseme{name, set.neutral.positions};
        for (Vec3& p : viseme.positions) p += offset;
        set.visemes.push_back(viseme);
    }
    return set;
}

FrequencySource closureFrequencies() {
    FrequencySource source;
    source.visemeFrequencies.entries = {{"sil", 0.3}, {"PP", 0.05}, {"aa", 0.25}, {"E", 0.2}, {"O", 0.2}};
    return source;
}

ReduceSettings settingsFor(int target, std::string closure) {
    ReduceSettings settings;
    settings.target = target;
    settings.rest = RestChoice::Free;
    settings.closure = std::move(closure);
    return settings;
}

int groupOfViseme(const ReduceOutcome& outcome, const std::string& name) {
    const std::vector<int> groupOf = outcome.result.groupOf();
    for (std::size_t i = 0; i < outcome.visemeNames.size(); ++i)
        if (outcome.visemeNames[i] == name) return groupOf[i];
    return -2;
}

std::size_t groupSize(const ReduceOutcome& outcome, int group) {
    const std::vector<int> groupOf = outcome.result.groupOf();
    return static_cast<std::size_t>(std::count(groupOf.begin(), groupOf.end(), group));
}

TEST(ClosureRule, WithoutItTheOptimumRestsTheClosure) {
    const ReduceOutcome outcome = runReduction(closureSet(), closureFrequencies(), settingsFor(3, ""));
    EXPECT_EQ(groupOfViseme(outcome, "PP"), kRestGroup); // the premise of the rule
    EXPECT_TRUE(outcome.closureViseme.empty());
    EXPECT_TRUE(outcome.closureNote.empty());
}

TEST(ClosureRule, AutoPinsPpAndIsTheOptimumUnderThatPin) {
    const VisemeSet set = closureSet();
    const ReduceOutcome rule = runReduction(set, closureFrequencies(), settingsFor(3, kClosureAuto));
    EXPECT_EQ(rule.closureViseme, "PP");
    const int group = groupOfViseme(rule, "PP");
    ASSERT_GE(group, 0);
    EXPECT_EQ(groupSize(rule, group), 1u);
    EXPECT_EQ(groupOfViseme(rule, "sil"), kRestGroup);
    // The same as the designer pinning PP, and dearer than the free optimum (the rule is a constraint).
    ReduceSettings pinned = settingsFor(3, "");
    pinned.constraints.pinned = {"PP"};
    const ReduceOutcome byHand = runReduction(set, closureFrequencies(), pinned);
    EXPECT_EQ(rule.result.groupOf(), byHand.result.groupOf());
    EXPECT_DOUBLE_EQ(rule.result.best().cost, byHand.result.best().cost);
    const ReduceOutcome free = runReduction(set, closureFrequencies(), settingsFor(3, ""));
    EXPECT_GT(rule.result.best().cost, free.result.best().cost);
    // The designer's constraints are what they gave, not the implicit pin.
    EXPECT_TRUE(rule.constraints.pinned.empty());
}

TEST(ClosureRule, NamedVisemeAndUnknownName) {
    const ReduceOutcome outcome = runReduction(closureSet(), closureFrequencies(), settingsFor(3, "E"));
    EXPECT_EQ(outcome.closureViseme, "E");
    EXPECT_EQ(groupSize(outcome, groupOfViseme(outcome, "E")), 1u);
    const std::string error = test::errorOf(
        [&] { runReduction(closureSet(), closureFrequencies(), settingsFor(3, "viseme_MBP")); });
    EXPECT_NE(error.find("--closure"), std::string::npos) << error;
    EXPECT_NE(error.find("viseme_MBP"), std::string::npos) << error;
}

TEST(ClosureRule, LeavesItToTheOptimiserWhenItCannotOrMustNotApply) {
    const VisemeSet set = closureSet();
    ReduceSettings keyed = settingsFor(3, kClosureAuto);
    keyed.rest = RestChoice::Key;
    const ReduceOutcome a = runReduction(set, closureFrequencies(), keyed);
    EXPECT_TRUE(a.closureViseme.empty());
    EXPECT_NE(a.closureNote.find("the rest is a key"), std::string::npos) << a.closureNote;

    ReduceSettings together = settingsFor(3, kClosureAuto);
    together.constraints.together = {{"PP", "O"}};
    const ReduceOutcome b = runReduction(set, closureFrequencies(), together);
    EXPECT_TRUE(b.closureViseme.empty());
    EXPECT_NE(b.closureNote.find("--together"), std::string::npos) << b.closureNote;
    EXPECT_EQ(groupOfViseme(b, "PP"), groupOfViseme(b, "O"));

    // m = 3 with aa, E, O pinned: no room for PP as a fourth key of its own.
    ReduceSettings crowded = settingsFor(3, kClosureAuto);
    crowded.constraints.pinned = {"aa", "E", "O"};
    const ReduceOutcome c = runReduction(set, closureFrequencies(), crowded);
    EXPECT_TRUE(c.closureViseme.empty());
    EXPECT_NE(c.closureNote.find("no room"), std::string::npos) << c.closureNote;

    ReduceSettings named = settingsFor(3, kClosureAuto);
    named.restViseme = "PP";
    const ReduceOutcome d = runReduction(set, closureFrequencies(), named);
    EXPECT_TRUE(d.closureViseme.empty());
    EXPECT_EQ(groupOfViseme(d, "PP"), kRestGroup);
}

TEST(ClosureRule, AutoWithoutAClosureVisemeDoesNothing) {
    VisemeSet set = closureSet();
    set.visemes[1].name = "FF";
    FrequencySource source = closureFrequencies();
    source.visemeFrequencies.entries[1].first = "FF";
    const ReduceOutcome outcome = runReduction(set, source, settingsFor(3, kClosureAuto));
    EXPECT_TRUE(outcome.closureViseme.empty());
    EXPECT_TRUE(outcome.closureNote.empty());
}

} // namespace
} // namespace vl
