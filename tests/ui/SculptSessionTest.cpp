// Sculpting through the session (issue 32): the dabs of one stroke are one undo step, the next
// stroke is another, and a blend becomes the selected viseme.
#include "ui/session/EditorSession.h"

#include <gtest/gtest.h>

namespace vl::ui {
namespace {

TEST(SculptSession, OneStrokeIsOneUndoStepAndTheNextStrokeAnother) {
    EditorSession session;
    session.files().loadSample();
    const int aa = session.visemes()->find("aa");
    ASSERT_GE(aa, 0);
    const std::vector<Vec3> original = session.visemes()->visemes[static_cast<std::size_t>(aa)].positions;
    std::vector<Vec3> shape = original;
    for (int dab = 1; dab <= 3; ++dab) {
        shape[5] += Vec3(0.0, 0.0, 0.1);
        session.authoring().sculptViseme(aa, shape, SculptTool::Grab);
    }
    session.history().endEdit();
    EXPECT_EQ(session.history().undoName(), "Sculpt aa (grab)");
    std::vector<Vec3> second = shape;
    second[9] += Vec3(0.1, 0.0, 0.0);
    session.authoring().sculptViseme(aa, second, SculptTool::Inflate);
    session.history().endEdit();
    EXPECT_EQ(session.visemes()->visemes[static_cast<std::size_t>(aa)].positions, second);
    session.history().undo();
    EXPECT_EQ(session.visemes()->visemes[static_cast<std::size_t>(aa)].positions, shape);
    session.history().undo();
    EXPECT_EQ(session.visemes()->visemes[static_cast<std::size_t>(aa)].positions, original);
}

TEST(SculptSession, ABlendIsAddedAndSelected) {
    EditorSession session;
    session.files().loadSample();
    const int aa = session.visemes()->find("aa"), ou = session.visemes()->find("ou");
    const std::size_t before = session.visemeCount();
    session.authoring().addBlendedViseme("aa-ou", {{aa, 0.5}, {ou, 0.5}});
    EXPECT_EQ(session.visemeCount(), before + 1);
    ASSERT_GE(session.selectedViseme(), 0);
    EXPECT_EQ(session.visemes()->visemes[static_cast<std::size_t>(session.selectedViseme())].name, "aa-ou");
    EXPECT_EQ(session.history().undoName(), "Blend aa-ou");
}

} // namespace
} // namespace vl::ui
