// Saving onto a file that exists asks first, and the window title names the project and shows
// unsaved changes (issue 30): real clicks and keys on the real window (Xvfb + xdotool).
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

namespace vl::test {
namespace {

std::string readText(const std::filesystem::path& file) {
    std::ifstream in(file);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SaveClicks, SavingOntoAnExistingFileAsksAndTheTitleShowsUnsavedChanges) {
    REQUIRE_GUI_TOOLS();
    const auto folder =
        std::filesystem::temp_directory_path() / ("visemelab-replace-" + std::to_string(getpid()));
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const auto mine = folder / "mine.vlproj";
    std::ofstream(mine) << "a file the designer wrote\n";

    GuiDriver gui({"--sample", "--panel", "Refinement"});
    gui.waitIdle();
    EXPECT_EQ(gui.windowTitle(), "Untitled - VisemeLab"); // the sample is read-only: it has no file

    // An edit marks the title.
    gui.click(gui.control(gui.document()["criterion"] == "normals" ? "depth" : "normals", "radio"));
    gui.waitIdle();
    EXPECT_EQ(gui.windowTitle(), "Untitled* - VisemeLab");

    // Save onto the designer's file: the dialog asks; Cancel keeps the file and the dialog open.
    gui.key("ctrl+s"); // the sample is read-only: Save asks for a file
    ASSERT_TRUE(gui.document()["file_dialog_open"].get<bool>());
    gui.chooseFile(mine, "Save");
    ASSERT_TRUE(gui.find("Replace", "button")) << "no question before replacing " << mine;
    gui.click(gui.control("Cancel", "button"));
    gui.waitFrames(2);
    EXPECT_EQ(readText(mine), "a file the designer wrote\n");
    EXPECT_TRUE(gui.document()["file_dialog_open"].get<bool>());
    EXPECT_FALSE(gui.find("Replace", "button"));

    // Asked again, Replace writes the project there.
    gui.chooseFile(mine, "Save");
    gui.click(gui.control("Replace", "button"));
    gui.waitIdle();
    EXPECT_EQ(gui.document()["project_path"], mine.string()) << gui.document()["messages"].dump();
    EXPECT_NE(readText(mine).find("\"visemes\""), std::string::npos);
    const std::string saved = gui.windowTitle();
    EXPECT_NE(saved.find("mine.vlproj - " + folder.string()), std::string::npos) << saved;
    EXPECT_EQ(saved.find('*'), std::string::npos) << saved;
    // Another edit marks the saved project's title.
    gui.click(gui.control(gui.document()["criterion"] == "normals" ? "depth" : "normals", "radio"));
    gui.waitIdle();
    EXPECT_EQ(gui.windowTitle().rfind("mine.vlproj* - ", 0), 0u) << gui.windowTitle();
    EXPECT_ALIVE(gui);
    std::filesystem::remove_all(folder);
}

} // namespace
} // namespace vl::test
