#include "ui/WindowTitle.h"

#include <gtest/gtest.h>

namespace vl::ui {
namespace {

TEST(WindowTitle, NamesTheProjectFileAndMarksUnsavedChanges) {
    EXPECT_EQ(windowTitle("/home/me/faces/face.vlproj", false), "face.vlproj - VisemeLab");
    EXPECT_EQ(windowTitle("/home/me/faces/face.vlproj", true), "face.vlproj* - VisemeLab");
    EXPECT_EQ(windowTitle({}, true), "Untitled* - VisemeLab");
}

} // namespace
} // namespace vl::ui
