// Round trips of random project states: save -> load gives the same state, and
// save -> load -> save gives byte-identical JSON.
#include "ProjectTestUtil.h"

#include "core/common/AtomicFile.h"
#include "core/project/Project.h"

namespace vl {
namespace {

using test::ScratchDir;

TEST(ProjectRoundTrip, RandomStatesSurviveSaveAndLoadExactly) {
    ScratchDir dir("roundtrip");
    std::mt19937_64 rng(20261121);
    for (int trial = 0; trial < 40; ++trial) {
        const auto file = dir / ("p" + std::to_string(trial) + ".vlproj");
        const Project original = test::randomProject(rng, file);
        saveProject(file, original);
        const std::string firstText = readFileToString(file);

        const Project loaded = loadProject(file);
        ASSERT_TRUE(loaded == original) << "trial " << trial << "\n" << firstText;

        saveProject(file, loaded);
        ASSERT_EQ(readFileToString(file), firstText) << "trial " << trial;
        ASSERT_TRUE(loadProject(file) == original) << "trial " << trial;
    }
}

// The same on the in-memory text, for many more states (file writes are fsync-bound).
TEST(ProjectRoundTrip, ManyRandomStatesSurviveTheJsonText) {
    ScratchDir dir("roundtrip_text");
    std::mt19937_64 rng(99);
    for (int trial = 0; trial < 400; ++trial) {
        const Project original = test::randomProject(rng, dir / "p.vlproj");
        const std::string text = projectToJsonText(original);
        const Project loaded = projectFromJsonText(text, original.path);
        ASSERT_TRUE(loaded == original) << "trial " << trial << "\n" << text;
        ASSERT_EQ(projectToJsonText(loaded), text) << "trial " << trial;
    }
}

TEST(ProjectRoundTrip, EqualityNoticesEveryKindOfChange) {
    ScratchDir dir("equality");
    std::mt19937_64 rng(7);
    Project base;
    do base = test::randomProject(rng, dir / "p.vlproj");
    while (base.visemes.size() < 2 || !base.reduction.result || base.frequencies.isPhonemeBased());
    ASSERT_TRUE(base == base);

    auto changed = [&](auto edit) {
        Project copy = base;
        edit(copy);
        return copy != base;
    };
    EXPECT_TRUE(changed([](Project& p) { p.path = "elsewhere.vlproj"; }));
    EXPECT_TRUE(changed([](Project& p) { p.visemes[0].name += "x"; }));
    EXPECT_TRUE(changed([](Project& p) { p.visemes[1].file = "other.obj"; }));
    EXPECT_TRUE(
        changed([](Project& p) { p.frequencies.visemeFrequencies.entries.emplace_back("extra", 1.0); }));
    EXPECT_TRUE(changed([](Project& p) {
        p.weights.mode = p.weights.mode == WeightMode::Area ? WeightMode::Uniform : WeightMode::Area;
    }));
    EXPECT_TRUE(changed([](Project& p) { p.weights.painted.push_back(1.0); }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.target += 1; }));
    EXPECT_TRUE(changed([](Project& p) {
        p.reduction.result->curve[0].cost = std::nextafter(p.reduction.result->curve[0].cost, 1e9);
    }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.result.reset(); }));
    EXPECT_TRUE(changed(
        [](Project& p) { p.reduction.result->curve[0].optimal = !p.reduction.result->curve[0].optimal; }));
    EXPECT_TRUE(changed([](Project& p) {
        p.reduction.result->method = p.reduction.result->method == ReductionMethod::SubsetDp
                                         ? ReductionMethod::BranchAndBound
                                         : ReductionMethod::SubsetDp;
    }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.result->method = ReductionMethod::ColumnGeneration; }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.constraints.pinned.push_back(p.visemes[0].name); }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.constraints.apart.emplace_back("x", "y"); }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.constraints.together.emplace_back("x", "y"); }));
    EXPECT_TRUE(changed([](Project& p) {
        p.reduction.rest = p.reduction.rest == RestChoice::Free ? RestChoice::Key : RestChoice::Free;
    }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.restViseme += "x"; }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.result->restFree = !p.reduction.result->restFree; }));
    EXPECT_TRUE(changed([](Project& p) { p.reduction.result->curve[0].rest.push_back(0); }));
    EXPECT_TRUE(changed([](Project& p) {
        p.editor.selectedViseme = p.editor.selectedViseme.empty() ? p.visemes[0].name : "";
    }));
}

TEST(ProjectRoundTrip, DoublesArePrintedSoTheyParseBackBitForBit) {
    ScratchDir dir("doubles");
    Project project;
    project.path = dir / "p.vlproj";
    project.neutral.embedded.positions = {
        {0.1, 1.0 / 3.0, 5e-324}, {1.7976931348623157e308, -0.0, 2.0 / 3.0}, {1e-300, 123456.789, -7.0}};
    project.neutral.embedded.triangles = {{0, 1, 2}};
    project.visemes = {{"a", {}, {{0.30000000000000004, 0, 0}, {0, 0, 0}, {0, 0, 0}}},
                       {"b", {}, {{1, 2, 3}, {4, 5, 6}, {7, 8, 9}}}};
    saveProject(project.path, project);
    const Project loaded = loadProject(project.path);
    for (std::size_t i = 0; i < 3; ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_EQ(std::bit_cast<std::uint64_t>(loaded.neutral.embedded.positions[i][c]),
                      std::bit_cast<std::uint64_t>(project.neutral.embedded.positions[i][c]));
    EXPECT_TRUE(loaded == project);
}

} // namespace
} // namespace vl
