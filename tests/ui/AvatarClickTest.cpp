// Avatars in the editor, driven with real clicks (xdotool on a private Xvfb): File > Import avatar...
// opens a generated Ready Player Me-like avatar (skinned, several meshes, ARKit targets around the
// visemes) as a document, the target pattern selects the visemes (undoable), weights are painted on
// the concatenated geometry, the project refers to the avatar by a relative path, and File > Export
// avatar... writes the same avatar with its visemes reduced.
#include "GuiDriver.h"
#include "core/common/AtomicFile.h"
#include "core/gltf/GltfDocument.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace vl::test {
namespace {

// A folder of its own per test, with the generated avatar in it.
struct AvatarFolder {
    std::filesystem::path dir, avatar;
    explicit AvatarFolder(const std::string& name) {
        dir = std::filesystem::temp_directory_path() /
              ("visemelab-avatar-clicks-" + name + "-" + std::to_string(getpid()));
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir / "avatars");
        avatar = dir / "avatars" / "rpm.glb";
        writeFileAtomically(avatar, rpmLikeAvatar());
    }
    ~AvatarFolder() { std::filesystem::remove_all(dir); }
};

// The file dialog's own control (the side panel has a "Save" button too).
nlohmann::json dialogControl(const GuiDriver& gui, const std::string& label, const std::string& kind) {
    for (const auto& control : gui.report()["controls"])
        if (control["label"] == label && control["kind"] == kind &&
            control["window"].get<std::string>().ends_with("###file-dialog"))
            return control;
    ADD_FAILURE() << "no " << kind << " '" << label << "' in the file dialog";
    return gui.control(label, kind);
}

// A control of the side panel, scrolled into view first (as a user scrolls the panel to reach it).
nlohmann::json revealed(GuiDriver& gui, const std::string& text, const std::string& kind) {
    for (int attempt = 0; attempt < 12; ++attempt) {
        const nlohmann::json control = gui.control(text, kind);
        if (control.value("visible", true)) return control;
        // Below the fold when it lies low in the window, else above it.
        gui.scroll(control["x"].get<double>() + 20, 400, control["y"].get<double>() > 400 ? 3 : -3);
    }
    return gui.control(text, kind);
}

// Types a path into the open file dialog's name field and presses its button ("Open" or "Save").
void chooseFile(GuiDriver& gui, const std::filesystem::path& file, const std::string& button) {
    ASSERT_TRUE(gui.document()["file_dialog_open"].get<bool>()) << gui.document().dump();
    gui.click(dialogControl(gui, "##name", "text"));
    gui.key("ctrl+a");
    gui.type(file.string());
    gui.click(dialogControl(gui, button, "button"));
    gui.waitIdle();
}

TEST(AvatarClicks, FileMenuImportsAnAvatarWithEveryMeshShown) {
    REQUIRE_GUI_TOOLS();
    const AvatarFolder folder("import");
    GuiDriver gui({});
    gui.waitIdle();
    ASSERT_TRUE(gui.document()["avatar"].is_null());
    gui.click(gui.control("File", "menu"));
    gui.click(gui.control("Import avatar...", "menuitem"));
    chooseFile(gui, folder.avatar, "Open");
    EXPECT_ALIVE(gui);
    const auto& avatar = gui.document()["avatar"];
    ASSERT_TRUE(avatar.is_object()) << gui.document()["messages"].dump();
    EXPECT_EQ(avatar["file"], folder.avatar.string());
    EXPECT_EQ(avatar["pattern"], "");
    EXPECT_EQ(avatar["visemes"].get<std::vector<std::string>>(), rpmVisemeNames());
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 15);
    // The head, teeth and eyes carry the visemes; the body is drawn greyed.
    int carriers = 0;
    bool bodyGreyed = false;
    for (const auto& mesh : avatar["meshes"]) {
        carriers += mesh["visemes"].get<bool>() ? 1 : 0;
        if (mesh["name"] == "Wolf3D_Body") bodyGreyed = !mesh["visemes"].get<bool>();
    }
    EXPECT_EQ(carriers, 4);
    EXPECT_TRUE(bodyGreyed) << avatar.dump();
    EXPECT_GT(avatar["greyed_vertices"].get<int>(), 0);
    // The import report: a row of the meshes table shows that mesh's primitives and targets, and why
    // the targets that are not visemes were left alone.
    EXPECT_EQ(gui.document()["avatar_mesh_report"], "");
    gui.click(revealed(gui, "Wolf3D_Head", "selectable"));
    const std::string head = gui.document()["avatar_mesh_report"].get<std::string>();
    EXPECT_NE(head.find("skinned"), std::string::npos) << head;
    EXPECT_NE(head.find("visemes: viseme_sil viseme_PP"), std::string::npos) << head;
    EXPECT_NE(head.find("kept as they are (not an Oculus viseme name): browInnerUp jawOpen"),
              std::string::npos)
        << head;
    gui.click(revealed(gui, "Wolf3D_Body (context)", "selectable"));
    EXPECT_NE(gui.document()["avatar_mesh_report"].get<std::string>().find("Wolf3D_Body"), std::string::npos);
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
    // The Visemes panel's button imports too (the document is unmodified: nothing to confirm).
    gui.click(revealed(gui, "Import avatar...", "button"));
    EXPECT_TRUE(gui.document()["file_dialog_open"].get<bool>());
    gui.click(dialogControl(gui, "Cancel", "button"));
    EXPECT_ALIVE(gui);
}

TEST(AvatarClicks, TargetPatternSelectsTheVisemesAndUndoes) {
    REQUIRE_GUI_TOOLS();
    const AvatarFolder folder("pattern");
    GuiDriver gui({"--avatar", folder.avatar.string()});
    gui.waitIdle();
    ASSERT_EQ(gui.document()["visemes"].get<int>(), 15) << gui.document()["messages"].dump();
    const auto setPattern = [&](const std::string& pattern) {
        gui.click(gui.control("##avatar-pattern", "text"));
        gui.key("ctrl+a");
        if (!pattern.empty()) gui.type(pattern);
        gui.click(gui.control("Apply pattern", "button"));
        gui.waitIdle();
    };
    setPattern("viseme_[aEIOU]*");
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 5) << gui.document()["messages"].dump();
    EXPECT_EQ(gui.document()["avatar"]["pattern"], "viseme_[aEIOU]*");
    EXPECT_EQ(gui.document()["undo"], "Viseme targets 'viseme_[aEIOU]*'");
    EXPECT_TRUE(gui.document()["modified"].get<bool>());
    // A pattern that selects one viseme is refused with the core's message; nothing changes.
    const auto before = gui.document()["document_revision"];
    setPattern("viseme_si*");
    EXPECT_TRUE(hasError(gui));
    EXPECT_NE(lastMessage(gui).find("at least 2"), std::string::npos) << lastMessage(gui);
    EXPECT_EQ(gui.document()["document_revision"], before);
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 5);
    // Undo restores the Oculus selection, and the field shows it again.
    gui.key("ctrl+z");
    gui.waitIdle();
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 15);
    EXPECT_EQ(gui.document()["avatar"]["pattern"], "");
    gui.key("ctrl+y");
    gui.waitIdle();
    EXPECT_EQ(gui.document()["visemes"].get<int>(), 5);
    EXPECT_ALIVE(gui);
}

TEST(AvatarClicks, WeightsArePaintedOnTheConcatenatedGeometry) {
    REQUIRE_GUI_TOOLS();
    const AvatarFolder folder("paint");
    // The brush starts as a subtracting one (the operation combo's items are not probed controls).
    GuiDriver gui({"--avatar", folder.avatar.string(), "--panel", "Weights", "--brush", "subtract"});
    gui.waitIdle();
    ASSERT_EQ(gui.document()["weight_mode"], "uniform");
    ASSERT_TRUE(gui.document()["brush"].get<bool>());
    const auto view = gui.control("main", "view");
    const double cx = view["x"].get<double>() + 0.5 * view["width"].get<double>();
    const double cy = view["y"].get<double>() + 0.5 * view["height"].get<double>();
    gui.drag(cx - 40, cy, cx + 40, cy + 10, 12);
    EXPECT_ALIVE(gui);
    EXPECT_EQ(gui.document()["undo"], "Paint stroke") << gui.document().dump();
    EXPECT_EQ(gui.document()["weight_mode"], "painted");
    const double mean = gui.document()["painted_mean"].get<double>();
    EXPECT_GT(mean, 0.0);
    EXPECT_LT(mean, 1.0); // subtracted under the brush, one per vertex of all four meshes
    EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
}

TEST(AvatarClicks, ReducedAvatarIsExportedAndTheProjectRefersToTheAvatar) {
    REQUIRE_GUI_TOOLS();
    const AvatarFolder folder("export");
    const std::string input = fileBytes(folder.avatar);
    {
        GuiDriver gui({"--avatar", folder.avatar.string(), "--panel", "Reduction"});
        gui.waitIdle();
        gui.click(gui.control("groups m", "slider"), 0.3);
        gui.waitIdle();
        const int m = gui.document()["target"].get<int>();
        ASSERT_GT(m, 1);
        ASSERT_LT(m, 15);

        // Export panel: merged names, then File > Export avatar... (the default name is beside the input).
        gui.click(gui.control("Export", "tab"));
        gui.click(gui.control("merged (one target per key)", "radio"));
        gui.click(gui.control("File", "menu"));
        gui.click(gui.control("Export avatar...", "menuitem"));
        const auto out = folder.dir / "out" / "rpm_reduced.glb";
        std::filesystem::create_directories(out.parent_path());
        chooseFile(gui, out, "Save");
        EXPECT_ALIVE(gui);
        ASSERT_TRUE(std::filesystem::is_regular_file(out)) << gui.document().dump();
        EXPECT_NE(lastMessage(gui).find("Exported the avatar: 15 visemes -> " + std::to_string(m) + " keys"),
                  std::string::npos)
            << lastMessage(gui);
        // The same avatar: every mesh, the visemes merged into m targets on each mesh carrying them.
        const GltfDocument in = loadGltfDocument(folder.avatar);
        const GltfDocument written = loadGltfDocument(out);
        EXPECT_EQ(written.model.meshes.size(), in.model.meshes.size());
        EXPECT_EQ(written.model.skins.size(), in.model.skins.size());
        EXPECT_EQ(written.model.materials.size(), in.model.materials.size());
        for (std::size_t i = 0; i < in.model.meshes.size(); ++i) {
            if (in.model.meshes[i].primitives[0].targets.empty()) continue;
            EXPECT_LT(written.model.meshes[i].primitives[0].targets.size(),
                      in.model.meshes[i].primitives[0].targets.size())
                << in.model.meshes[i].name;
        }
        EXPECT_TRUE(written.json["extras"].contains("visemelab"));
        EXPECT_EQ(written.json["extras"]["visemelab"]["names"], "merged");
        EXPECT_EQ(written.json["extras"]["visemelab"]["keys"].size(), static_cast<std::size_t>(m));
        // The export says which target now carries which key (the Export panel lists it).
        const auto& keys = gui.document()["reduction"]["last_avatar_export"];
        ASSERT_GE(keys.size(), static_cast<std::size_t>(m)) << keys;
        for (int g = 0; g < m; ++g)
            EXPECT_EQ(keys[static_cast<std::size_t>(g)].get<std::string>().rfind(
                          "key " + std::to_string(g) + " (", 0),
                      0u)
                << keys;
        EXPECT_NE(keys[0].get<std::string>().find("' on "), std::string::npos) << keys;

        // The export button refuses the input itself, even after "Replace"; the input is untouched.
        gui.click(gui.control("Export avatar...", "button"));
        chooseFile(gui, folder.avatar, "Save");
        gui.click(dialogControl(gui, "Replace", "button"));
        gui.waitIdle();
        EXPECT_TRUE(hasError(gui));
        EXPECT_NE(lastMessage(gui).find("is the avatar the document was read from"), std::string::npos)
            << lastMessage(gui);
        EXPECT_EQ(fileBytes(folder.avatar), input);

        // Saved, the project names the avatar relative to itself.
        std::filesystem::create_directories(folder.dir / "project");
        gui.key("ctrl+s");
        chooseFile(gui, folder.dir / "project" / "avatar.vlproj", "Save");
        EXPECT_FALSE(gui.document()["modified"].get<bool>()) << gui.document()["messages"].dump();
    }
    const auto saved = nlohmann::json::parse(fileBytes(folder.dir / "project" / "avatar.vlproj"));
    EXPECT_EQ(saved["avatar"]["file"], "../avatars/rpm.glb");
    EXPECT_TRUE(saved["neutral"].is_null());
    // Reopened, it is the avatar again with its visemes and target.
    GuiDriver again({"--project", (folder.dir / "project" / "avatar.vlproj").string()});
    again.waitIdle();
    EXPECT_ALIVE(again);
    ASSERT_TRUE(again.document()["avatar"].is_object()) << again.document()["messages"].dump();
    EXPECT_EQ(again.document()["avatar"]["file"], folder.avatar.string());
    EXPECT_EQ(again.document()["visemes"].get<int>(), 15);
    EXPECT_EQ(again.document()["target"], saved["reduction"]["target"]);
    // A new avatar document is rest-free (viseme_sil rests); the file keeps the model and its result.
    EXPECT_EQ(saved["reduction"]["rest"], "auto");
    EXPECT_EQ(saved["reduction"]["result"]["restFree"], true);
    EXPECT_EQ(again.document()["reduction"]["rest"]["resolved"], "viseme_sil");
    EXPECT_FALSE(hasError(again)) << again.document()["messages"].dump();
}

// The Export panel offers gltfpack re-compression: on by default for an avatar read compressed
// (meshopt), so it goes out compressed; a real click turns it off. Without gltfpack the option is
// greyed with a note saying how to get it. Skips loudly when the build folder has no gltfpack
// (installed by the gltfpack_install test).
TEST(AvatarClicks, ExportRecompressesWithGltfpackWhenChosen) {
    REQUIRE_GUI_TOOLS();
    const std::filesystem::path gltfpack = VISEMELAB_GLTFPACK_INSTALLED;
    if (!std::filesystem::exists(gltfpack))
        GTEST_SKIP() << "no gltfpack at " << gltfpack << " (ctest -R gltfpack_install installs it)";
    AvatarFolder folder("gltfpack");
    writeFileAtomically(folder.avatar, rpmLikeAvatar({.storage = FixtureStorage::Meshopt}));
    const auto usesMeshopt = [](const std::filesystem::path& file) {
        const GltfDocument written = loadGltfDocument(file);
        const auto used = written.json.value("extensionsUsed", nlohmann::json::array());
        return std::find(used.begin(), used.end(), "EXT_meshopt_compression") != used.end();
    };
    const auto exportTo = [](GuiDriver& gui, const std::filesystem::path& out) {
        gui.click(gui.control("Export avatar...", "button"));
        chooseFile(gui, out, "Save");
        for (int i = 0; i < 600 && !std::filesystem::exists(out) && !hasError(gui); ++i) gui.waitFrames(1);
        gui.waitIdle();
    };
    std::filesystem::create_directories(folder.dir / "out");
    const std::string option = "re-compress with gltfpack (meshopt + quantised, like real exporters)";
    {
        ::setenv("VISEMELAB_GLTFPACK", gltfpack.c_str(), 1);
        GuiDriver gui({"--avatar", folder.avatar.string(), "--panel", "Export"});
        ::unsetenv("VISEMELAB_GLTFPACK");
        gui.waitIdle();
        gui.control(option, "checkbox");
        EXPECT_TRUE(gui.document()["avatar_gltfpack"].get<bool>())
            << "a compressed avatar goes out compressed";
        const auto packed = folder.dir / "out" / "packed.glb";
        exportTo(gui, packed);
        ASSERT_TRUE(std::filesystem::is_regular_file(packed)) << gui.document()["messages"].dump();
        EXPECT_NE(lastMessage(gui).find("re-compressed with gltfpack"), std::string::npos)
            << lastMessage(gui);
        EXPECT_TRUE(usesMeshopt(packed));

        gui.click(gui.control(option, "checkbox"));
        EXPECT_FALSE(gui.document()["avatar_gltfpack"].get<bool>());
        const auto plain = folder.dir / "out" / "plain.glb";
        exportTo(gui, plain);
        ASSERT_TRUE(std::filesystem::is_regular_file(plain)) << gui.document()["messages"].dump();
        // Untouched meshes keep their meshopt buffers either way; only the re-compressed file is smaller.
        EXPECT_EQ(lastMessage(gui).find("re-compressed with gltfpack"), std::string::npos)
            << lastMessage(gui);
        EXPECT_LT(std::filesystem::file_size(packed), std::filesystem::file_size(plain));
        EXPECT_FALSE(hasError(gui)) << gui.document()["messages"].dump();
    }
    ::setenv("VISEMELAB_GLTFPACK", "/nonexistent/gltfpack", 1);
    GuiDriver without({"--avatar", folder.avatar.string(), "--panel", "Export"});
    ::unsetenv("VISEMELAB_GLTFPACK");
    without.waitIdle();
    EXPECT_TRUE(
        without.find("gltfpack not found: install it with `npm install -g gltfpack` (or a native build "
                     "from meshoptimizer), or set VISEMELAB_GLTFPACK to its path",
                     "text"))
        << without.report()["controls"].dump();
    EXPECT_FALSE(without.document()["avatar_gltfpack"].get<bool>());
    EXPECT_ALIVE(without);
}

} // namespace
} // namespace vl::test
