// Issue 14's small things, below the GUI: a glTF import keeps its frequencies and is unsaved, the
// status line's messages expire, the refinement reports refined and coarsened counts.
#include "ui/session/EditorSession.h"
#include "ui/widgets/FrequencyHistogram.h"
#include "ui/widgets/StatusLine.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

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
    session.files().loadSample();
    ASSERT_TRUE(session.document().frequencies.isPhonemeBased()) << "the sample counts phonemes";
    // Every viseme its own key: the keyed model, since with the sample's free rest sil is no key.
    session.reduction().setRest(RestChoice::Key, "");
    session.reduction().setTarget(static_cast<int>(session.visemeCount()));
    session.finishBackgroundWork();
    session.files().exportProject(ExportFormat::Glb, dir / "face.glb");
    const std::vector<double> exported = session.frequencies().values();

    EditorSession imported;
    imported.files().importGltf(dir / "face.glb");
    ASSERT_EQ(imported.visemeCount(), session.visemeCount());
    EXPECT_TRUE(imported.document().frequencies.isPhonemeBased()) << "the phoneme table and map came back";
    const std::vector<double> got = imported.frequencies().values();
    ASSERT_EQ(got.size(), exported.size());
    for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], exported[i], 1e-9) << i;
    // The geometry exists only in memory: unsaved, untitled, and a quit would ask first.
    EXPECT_TRUE(imported.history().modified());
    EXPECT_TRUE(imported.files().path().empty());
    imported.files().saveProject(dir / "imported.vlproj");
    EXPECT_FALSE(imported.history().modified());
    // The saved project reopens with the same frequencies.
    EditorSession reopened;
    reopened.files().openProject(dir / "imported.vlproj");
    const std::vector<double> again = reopened.frequencies().values();
    for (std::size_t i = 0; i < again.size(); ++i) EXPECT_NEAR(again[i], exported[i], 1e-9) << i;
    EXPECT_FALSE(reopened.history().modified());
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

// The histogram's names: the fewest rows in which no two names on a row overlap, checked against
// the definition on random widths.
TEST(FrequencyHistogram, LabelRowsAreTheFewestWithoutOverlap) {
    const std::vector<float> narrow = {20, 18, 22};
    EXPECT_EQ(labelRows(narrow, 40.0f, 6.0f), 1);
    const std::vector<float> wide = {50, 50, 50, 50};
    EXPECT_EQ(labelRows(wide, 30.0f, 6.0f), 2); // 56 > 30 but <= 60
    EXPECT_EQ(labelRows(wide, 10.0f, 6.0f), 4) << "one name per row at most";
    std::uint32_t state = 12345;
    auto next = [&] { return (state = state * 1664525u + 1013904223u) >> 8; };
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<float> widths(1 + next() % 40);
        for (float& w : widths) w = static_cast<float>(5 + next() % 80);
        const float bar = static_cast<float>(4 + next() % 60);
        auto overlapFree = [&](int rows) {
            for (std::size_t i = 0; i < widths.size(); ++i)
                for (std::size_t j = i + 1; j < widths.size(); ++j)
                    if ((j - i) % static_cast<std::size_t>(rows) == 0 &&
                        0.5f * (widths[i] + widths[j]) + 6.0f > static_cast<float>(j - i) * bar)
                        return false;
            return true;
        };
        const int rows = labelRows(widths, bar, 6.0f);
        EXPECT_TRUE(overlapFree(rows)) << trial; // one name per row (rows = n) is overlap-free too
        for (int fewer = 1; fewer < rows; ++fewer) EXPECT_FALSE(overlapFree(fewer)) << trial;
    }
}

} // namespace
} // namespace vl::ui

namespace vl::ui {
namespace {

// Issue 32: a new document (the sample again, a set built from the face) drops the old clip and
// the selection, and says so by a new epoch; an edit does not.
TEST(NewDocument, DropsTheClipAndTheSelectionOnEveryReplacement) {
    EditorSession session;
    session.files().loadSample();
    const auto loaded = session.history().documentEpoch();
    session.speech().playSequence("PP aa", 0.2);
    ASSERT_TRUE(session.speech().clip());
    session.selectViseme(3);
    session.reduction().setTarget(8);
    EXPECT_EQ(session.history().documentEpoch(), loaded) << "an edit is the same document";
    EXPECT_TRUE(session.speech().clip());
    session.files().loadSample();
    EXPECT_GT(session.history().documentEpoch(), loaded);
    EXPECT_FALSE(session.speech().clip()) << "the old clip is not the new document's";
    session.speech().playSequence("", 0.2);
    session.selectViseme(2);
    session.face().load();
    const auto beforeBuild = session.history().documentEpoch();
    session.face().generateVisemes();
    EXPECT_GT(session.history().documentEpoch(), beforeBuild);
    EXPECT_FALSE(session.speech().clip());
    EXPECT_EQ(session.selectedViseme(), -1);
    session.files().newProject();
    EXPECT_FALSE(session.speech().clip());
}

// A message that starts with the action's name is not prefixed again ("Constraints: constraints:").
TEST(Messages, AnActionNamedByItsMessageIsNotRepeated) {
    EditorSession session;
    session.attempt("Constraints", [] { throw std::runtime_error("constraints: no viseme 'xx'"); });
    EXPECT_EQ(session.messages().back().text, "Constraints: no viseme 'xx'");
    session.attempt("Save", [] { throw std::runtime_error("disk full"); });
    EXPECT_EQ(session.messages().back().text, "Save: disk full");
}

} // namespace
} // namespace vl::ui
