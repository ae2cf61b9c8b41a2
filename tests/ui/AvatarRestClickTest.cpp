// "Add rest viseme" on an avatar project whose visemes lack one (issue 29), driven with real clicks
// (xdotool on a private Xvfb, see GuiDriver.h): the Reduction panel's Model section adds viseme_sil
// (the base mesh, no target) in one undoable step, it rests with the rest free, and the saved project
// records it; the Frequencies panel's rest row adds it under the name typed.
#include "GuiDriver.h"
#include "core/common/AtomicFile.h"
#include "core/document/AvatarDocument.h"
#include "core/project/Project.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

namespace vl::test {
namespace {

// A generated Ready Player Me-like avatar without viseme_sil and its project (as `project new
// --avatar --no-add-rest` writes it), in a folder of their own.
struct NoRestProject {
    std::filesystem::path dir, project;
    NoRestProject() {
        dir = std::filesystem::temp_directory_path() /
              ("visemelab-avatar-rest-clicks-" + std::to_string(getpid()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        AvatarFixtureOptions options;
        options.restTarget = false;
        writeFileAtomically(dir / "norest.glb", rpmLikeAvatar(options));
        project = dir / "norest.vlproj";
        // No table needed: without sil the Oculus map does not fit, so the defaults are equal frequencies.
        saveProject(project, newAvatarProject(dir / "norest.glb", "", {}));
    }
    ~NoRestProject() { std::filesystem::remove_all(dir); }
};

const nlohmann::json& restModel(const GuiDriver& gui) {
    return gui.document()["reduction"]["rest"];
}

bool restsIn(const GuiDriver& gui, const std::string& name) {
    const nlohmann::json& current = gui.document()["reduction"]["current"];
    if (current.is_null()) return false;
    const auto names = current["resting"].get<std::vector<std::string>>();
    return std::find(names.begin(), names.end(), name) != names.end();
}

TEST(AvatarRestClicks, AddRestVisemeGivesAnAvatarWithoutOneTheBaseMeshAsItsRest) {
    REQUIRE_GUI_TOOLS();
    const NoRestProject files;
    GuiDriver gui({"--project", files.project.string(), "--panel", "Reduction"});
    gui.waitIdle();
    ASSERT_TRUE(gui.document()["avatar"].is_object()) << gui.document()["messages"].dump();
    ASSERT_EQ(gui.document()["visemes"].get<int>(), 14);
    EXPECT_EQ(gui.document()["avatar"]["added_rest"], "");
    // Auto without a rest viseme: the rest is a key.
    EXPECT_FALSE(restModel(gui)["free"].get<bool>()) << restModel(gui);
    EXPECT_EQ(restModel(gui)["resolved"], "");

    gui.click(gui.reveal("Add rest viseme", "button"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 15);
    EXPECT_EQ(gui.document()["undo"], "Add rest viseme viseme_sil");
    EXPECT_EQ(gui.document()["avatar"]["added_rest"], "viseme_sil");
    EXPECT_EQ(gui.document()["avatar"]["visemes"].back(), "viseme_sil");
    EXPECT_TRUE(restModel(gui)["free"].get<bool>());
    EXPECT_EQ(restModel(gui)["resolved"], "viseme_sil");
    EXPECT_TRUE(restsIn(gui, "viseme_sil")) << gui.document()["reduction"].dump();
    EXPECT_FALSE(gui.find("Add rest viseme", "button")); // the set has its rest now

    // Saved, the project records it (version 4); undo gives the avatar's 14 visemes back.
    gui.key("ctrl+s");
    gui.waitIdle();
    EXPECT_FALSE(gui.document()["modified"].get<bool>()) << gui.document()["messages"].dump();
    const auto saved = nlohmann::json::parse(fileBytes(files.project));
    EXPECT_EQ(saved["version"], 4);
    EXPECT_EQ(saved["avatar"]["addedRest"], "viseme_sil");
    EXPECT_EQ(saved["visemes"].back()["name"], "viseme_sil");
    gui.key("ctrl+z");
    gui.waitIdle();
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 14);
    EXPECT_EQ(gui.document()["avatar"]["added_rest"], "");
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

TEST(AvatarRestClicks, TheFrequencyPanelsRestRowNamesTheAvatarsRest) {
    // Starting a phoneme map on the avatar, the designer types "sil" and adds it: the avatar gains its
    // rest under that name (no target), and the pause row of the map takes it.
    REQUIRE_GUI_TOOLS();
    const NoRestProject files;
    GuiDriver gui({"--project", files.project.string(), "--panel", "Frequencies", "--map-start", "oculus"});
    gui.waitIdle();
    ASSERT_EQ(gui.document()["visemes"].get<int>(), 14) << gui.document()["messages"].dump();
    ASSERT_TRUE(gui.document()["map_start_open"].get<bool>());
    const int unassigned = gui.document()["map_start_unassigned"].get<int>();

    gui.click(gui.reveal("##rest-name", "text"));
    gui.key("ctrl+a");
    gui.type("sil");
    gui.click(gui.reveal("Add rest viseme", "button"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 15);
    EXPECT_EQ(gui.document()["undo"], "Add rest viseme sil");
    EXPECT_EQ(gui.document()["avatar"]["added_rest"], "sil");
    EXPECT_LT(gui.document()["map_start_unassigned"].get<int>(), unassigned); // the pause row took it

    // Another name is refused with the names allowed, and nothing changes.
    gui.key("ctrl+z");
    gui.waitIdle();
    gui.click(gui.reveal("##rest-name", "text"));
    gui.key("ctrl+a");
    gui.type("pause");
    gui.click(gui.reveal("Add rest viseme", "button"));
    gui.waitIdle();
    EXPECT_TRUE(hasError(gui));
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 14);
}

} // namespace
} // namespace vl::test
