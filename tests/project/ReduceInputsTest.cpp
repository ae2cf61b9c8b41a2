// The one place reductions and reduced models come from (core/project/ReduceInputs.h): its time
// limit policy, its frequency-table rule, and the reduced model from a known grouping or a fresh run.
#include "core/project/ReduceInputs.h"
#include "core/common/Error.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

// Five visemes on one triangle, moving one vertex by 0, 1, 1.1, 5 and 5.2.
ReduceInputs smallInputs(int target) {
    auto set = std::make_shared<VisemeSet>();
    set->neutral.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    set->neutral.triangles = {Triangle{0, 1, 2}};
    const std::pair<const char*, double> shapes[] = {
        {"sil", 0.0}, {"A", 1.0}, {"B", 1.1}, {"C", 5.0}, {"D", 5.2}};
    ReduceInputs inputs;
    for (const auto& [name, dz] : shapes) {
        Viseme viseme{name, set->neutral.positions};
        viseme.positions[0] = Vec3(0, 0, dz);
        set->visemes.push_back(viseme);
        inputs.frequencies.visemeFrequencies.entries.emplace_back(name, 1.0);
    }
    inputs.set = std::move(set);
    inputs.settings.target = target;
    return inputs;
}

// Key names and shapes: what a reduced model shows.
void expectSameKeys(const ReducedModel& a, const ReducedModel& b) {
    ASSERT_EQ(a.keys.size(), b.keys.size());
    for (std::size_t k = 0; k < a.keys.size(); ++k) {
        EXPECT_EQ(a.keys[k].name, b.keys[k].name);
        EXPECT_EQ(a.keys[k].positions, b.keys[k].positions);
    }
    EXPECT_EQ(a.resting, b.resting);
}

TEST(ReducePolicy, BatchLimitsEverySetAndInteractiveOnlyTheLargeOnes) {
    EXPECT_EQ(ReducePolicy::batch().timeLimitFor(5), kBatchReduceSeconds);
    EXPECT_EQ(ReducePolicy::batch(3).timeLimitFor(40), 3.0);
    EXPECT_EQ(ReducePolicy::batch(0).timeLimitFor(40), 0.0);
    EXPECT_EQ(ReducePolicy::interactive().timeLimitFor(kMaxExactVisemes), 0.0);
    EXPECT_EQ(ReducePolicy::interactive().timeLimitFor(kMaxExactVisemes + 1), kInteractiveReduceSeconds);
    EXPECT_EQ(withPolicy({}, ReducePolicy::batch(7), 5).options.timeLimitSeconds, 7.0);
}

TEST(ReduceInputs, AMapMakesTheTableAPhonemeTable) {
    FrequencySource table;
    table.visemeFrequencies.entries = {{"AA", 2.0}, {"P", 1.0}};
    PhonemeVisemeMap map;
    map.entries = {{"AA", "aa"}, {"P", "PP"}};
    const FrequencySource mapped = withPhonemeMap(table, map);
    EXPECT_TRUE(mapped.isPhonemeBased());
    EXPECT_EQ(mapped.phonemes, table.visemeFrequencies);
    EXPECT_TRUE(mapped.visemeFrequencies.entries.empty());
    EXPECT_EQ(mapped.map, map);
    EXPECT_EQ(withPhonemeMap(mapped, map), mapped); // a phoneme table stays one
    requirePhonemeMap(mapped, "--freq-file");
    FrequencySource unmapped = mapped;
    unmapped.map = {};
    EXPECT_THROW(requirePhonemeMap(unmapped, "--freq-file"), InputError);
    requirePhonemeMap(table, "--freq-file"); // a viseme table needs none
}

TEST(ReduceInputs, AKnownGroupingBuildsTheModelAFreshRunOtherwise) {
    const ReduceInputs inputs = smallInputs(3);
    const ReduceOutcome fresh = reduce(inputs, ReducePolicy::batch());
    ASSERT_EQ(fresh.result.curve.size(), 3u);
    expectSameKeys(reducedModel(inputs, nullptr, ReducePolicy::batch()), fresh.model);
    expectSameKeys(reducedModel(inputs, &fresh.result.best(), ReducePolicy::batch()), fresh.model);
    EXPECT_EQ(reducedGrouping(inputs, nullptr, ReducePolicy::batch()), fresh.result.groupOf());
    // A known grouping is used as it is, even one the optimum would not choose.
    Grouping known;
    known.groups = {{0, 3}, {1, 4}, {2}};
    EXPECT_EQ(reducedGrouping(inputs, &known, ReducePolicy::batch()), known.groupOf());
    const ReducedModel model = reducedModel(inputs, &known, ReducePolicy::batch());
    ASSERT_EQ(model.keys.size(), 3u);
    EXPECT_EQ(model.keys[0].members, (std::vector<std::string>{"sil", "C"}));
}

TEST(ReduceInputs, ARecordedResultCountsOnlyForTheSameTargetAndRestModel) {
    const ReduceInputs inputs = smallInputs(3);
    std::optional<ReductionResult> recorded = reduce(inputs, ReducePolicy::batch()).result;
    EXPECT_EQ(recordedGrouping(inputs, recorded), &recorded->best());
    EXPECT_EQ(recordedGrouping(inputs, std::nullopt), nullptr);
    EXPECT_EQ(recordedGrouping(smallInputs(2), recorded), nullptr); // another target
    ReduceInputs free = inputs;
    free.settings.rest = RestChoice::Free; // the set has sil: the rest-free model
    EXPECT_EQ(recordedGrouping(free, recorded), nullptr);
    recorded->restFree = true;
    EXPECT_EQ(recordedGrouping(free, recorded), &recorded->best());
}

} // namespace
} // namespace vl
