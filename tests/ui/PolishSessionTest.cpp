// Issue 14's small things, below the GUI: a glTF import keeps its frequencies and is unsaved, the
// status line's messages expire, the refinement reports refined and coarsened counts.
#include "ui/session/EditorSession.h"
#include "ui/widgets/StatusLine.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl::ui {
namespace {

std::filesystem::path freshDir(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / ("visemelab-polish-" + std::string(name));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(GltfImport, KeepsTheFrequenciesAndIsUnsavedUntilSaved) {
    const auto dir = freshDir("import");
    EditorSession session;
    session.loadSample();
    ASSERT_TRUE(session.document().frequencies.isPhonemeBased()) << "the sample counts phonemes";
    session.setTarget(static_cast<int>(session.visemeCount())); // every viseme its own key
    session.finishBackgroundWork();
    session.exportProject(ExportFormat::Glb, dir / "face.glb");
    const std::vector<double> exported = session.visemeFrequencies();

    EditorSession imported;
    imported.importGltf(dir / "face.glb");
    ASSERT_EQ(imported.visemeCount(), session.visemeCount());
    EXPECT_TRUE(imported.document().frequencies.isPhonemeBased()) << "the phoneme table and map came back";
    const std::vector<double> got = imported.visemeFrequencies();
    ASSERT_EQ(got.size(), exported.size());
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], exported[i], 1e-9) << i;
    // The geometry exists only in memory: unsaved, untitled, and a quit would ask first.
    EXPECT_TRUE(imported.modified());
    EXPECT_TRUE(imported.path().empty());
    imported.saveProject(dir / "imported.vlproj");
    EXPECT_FALSE(imported.modified());
    // The saved project reopens with the same frequencies.
    EditorSession reopened;
    reopened.openProject(dir / "imported.vlproj");
    const std::vector<double> again = reopened.visemeFrequencies();
    for (std::size_t i = 0; i < again.size(); ++i) EXPECT_NEAR(again[i], exported[i], 1e-9) << i;
    EXPECT_FALSE(reopened.modified());
}

TEST(StatusLine, MessagesExpireAfterTheirTimeFromWhenTheyFirstShow) {
    StatusLine line;
    const StatusMessage info{StatusMessage::Kind::Info, "Saved", 1};
    const StatusMessage error{StatusMessage::Kind::Error, "Open project: bad file", 2};
    EXPECT_EQ(line.update(nullptr, 0.0, false), nullptr);
    // Posted long before it could show (a busy frame): its time starts when it shows.
    EXPECT_EQ(line.update(&info, 100.0, false), &info);
    EXPECT_EQ(line.update(&info, 100.0 + StatusLine::kInfoSeconds - 0.1, false), &info);
    EXPECT_EQ(line.update(&info, 100.0 + StatusLine::kInfoSeconds + 0.1, false), nullptr);
    EXPECT_EQ(line.update(&info, 100.0 + 2.0 * StatusLine::kInfoSeconds, true), nullptr) << "gone stays gone";
    // A new message shows at once; errors stay longer; the pointer on the bar holds it.
    EXPECT_EQ(line.update(&error, 200.0, false), &error);
    EXPECT_EQ(line.update(&error, 200.0 + StatusLine::kInfoSeconds + 1.0, false), &error);
    EXPECT_EQ(line.update(&error, 200.0 + StatusLine::kErrorSeconds - 1.0, true), &error); // hovered: restart
    EXPECT_EQ(line.update(&error, 200.0 + StatusLine::kErrorSeconds + 1.0, false), &error);
    EXPECT_EQ(line.update(&error, 200.0 + 2.0 * StatusLine::kErrorSeconds, false), nullptr);
}

TEST(StatusLine, SessionMessagesAreNumberedInOrder) {
    EditorSession session;
    session.info("one");
    session.error("two");
    ASSERT_GE(session.messages().size(), 2u);
    const auto& all = session.messages();
    EXPECT_EQ(all[all.size() - 1].serial, all[all.size() - 2].serial + 1);
    EXPECT_EQ(all.back().kind, StatusMessage::Kind::Error);
}

} // namespace
} // namespace vl::ui
