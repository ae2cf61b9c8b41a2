// docs/project-format.md stays true: its complete example loads, and it is exactly what saving
// that state writes (so the documented layout is the real one).
#include "ProjectTestUtil.h"

#include "core/common/AtomicFile.h"

namespace vl {
namespace {

std::string jsonBlockAfter(const std::string& text, const std::string& heading) {
    const auto at = text.find(heading);
    if (at == std::string::npos) return {};
    const auto open = text.find("```json\n", at);
    const auto close = text.find("```\n", open + 8);
    if (open == std::string::npos || close == std::string::npos) return {};
    return text.substr(open + 8, close - open - 8);
}

TEST(ProjectDocs, CompleteExampleLoadsAndIsWhatSavingWrites) {
    const auto doc = std::filesystem::path(VISEMELAB_ASSETS_DIR).parent_path() / "docs" / "project-format.md";
    const std::string example = jsonBlockAfter(readFileToString(doc), "## Complete example");
    ASSERT_FALSE(example.empty()) << "no json block under '## Complete example' in " << doc;

    const Project p = projectFromJsonText(example, "/nowhere/example.vlproj", false);
    EXPECT_EQ(p.visemes.size(), 4u);
    EXPECT_TRUE(p.deformation.isSet());
    EXPECT_EQ(p.refinement.kind, CriterionKind::Contour);
    ASSERT_TRUE(p.reduction.result);
    EXPECT_EQ(projectToJsonText(p), example);
}

TEST(ProjectDocs, Version0ExampleMigrates) {
    const auto doc = std::filesystem::path(VISEMELAB_ASSETS_DIR).parent_path() / "docs" / "project-format.md";
    const std::string example = jsonBlockAfter(readFileToString(doc), "## Version 0 and migration");
    ASSERT_FALSE(example.empty());
    // The example lists both frequency forms to show them; keep one, as the text says.
    std::string direct = example;
    const auto from = direct.find("  \"phonemes\"");
    const auto to = direct.find("  \"weights\"");
    direct.erase(from, to - from);
    const Project p = projectFromJsonText(direct, "/nowhere/old.vlproj", false);
    EXPECT_EQ(p.visemes.size(), 2u);
    EXPECT_EQ(p.weights.mode, WeightMode::Area);
    EXPECT_INPUT_ERROR(projectFromJsonText(example, "/nowhere/old.vlproj", false),
                       "/frequencies: give either \"visemes\" or \"phonemes\" with \"map\", not both");
}

} // namespace
} // namespace vl
