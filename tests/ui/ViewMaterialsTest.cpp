// The materials the views draw (ui/ViewMaterials.h): read once per source (an OBJ neutral mesh's
// .mtl, an avatar's scan), not again for edits of the same set; warnings and errors become status
// messages and an error leaves the views without materials.
#include "ui/session/ViewMaterials.h"
#include "core/document/AvatarDocument.h"
#include "core/document/Commands.h"
#include "tests/common/TestImages.h"
#include "tests/gltf/TexturedAvatar.h"
#include "ui/session/EditorSession.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace vl::ui {
namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto folder = std::filesystem::temp_directory_path() / ("visemelab_view_materials_" + name);
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

void write(const std::filesystem::path& file, const std::string& bytes) {
    std::ofstream(file, std::ios::binary) << bytes;
}

// A quad in material "skin" (a 2x2 texture), with `lift` on its first vertex.
std::string quadObj(double lift) {
    return "mtllib head.mtl\nv 0 0 " + std::to_string(lift) +
           "\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl skin\nf 1/1 2/2 3/3 4/4\n";
}

bool anyMessage(const EditorSession& session, const std::string& text, StatusMessage::Kind kind) {
    for (const StatusMessage& m : session.messages())
        if (m.kind == kind && m.text.find(text) != std::string::npos) return true;
    return false;
}

TEST(ViewMaterials, ObjFolderReadOnceThenDroppedWithAnotherDocument) {
    const auto folder = scratch("obj");
    write(folder / "skin.png", test::pngBytes(2, 2, test::solidRgba(2, 2, 200, 100, 50)));
    write(folder / "head.mtl", "newmtl skin\nmap_Kd skin.png\n");
    write(folder / "neutral.obj", quadObj(0.0));
    write(folder / "aa.obj", quadObj(0.2));
    write(folder / "oh.obj", quadObj(0.1));
    EditorSession session;
    session.files().loadVisemeFolder(folder);
    ASSERT_NE(session.visemes(), nullptr);
    ViewMaterials shown;
    EXPECT_TRUE(refreshViewMaterials(shown, session.document(), session));
    ASSERT_TRUE(shown.any());
    EXPECT_EQ(shown.visemes.ranges.size(), 1u);
    EXPECT_EQ(shown.visemes.cornerTexCoords.size(), session.visemes()->neutral.triangles.size());
    ASSERT_EQ(shown.materials.images.size(), 1u);
    EXPECT_EQ(shown.summary(), "1 materials, 1 textures (0.0 MiB)");
    // The same source: nothing read again.
    EXPECT_FALSE(refreshViewMaterials(shown, session.document(), session));
    session.files().loadSample();
    EXPECT_TRUE(refreshViewMaterials(shown, session.document(), session));
    EXPECT_FALSE(shown.any());
    std::filesystem::remove_all(folder);
}

TEST(ViewMaterials, AvatarKeptAcrossEditsWarningsAndErrorsAreMessages) {
    const auto folder = scratch("avatar");
    write(folder / "textured.glb", test::texturedAvatar());
    EditorSession session;
    const Document document = documentFromAvatar(loadDocumentAvatar(folder / "textured.glb", ""), {});
    ViewMaterials shown;
    EXPECT_TRUE(refreshViewMaterials(shown, document, session));
    ASSERT_TRUE(shown.any());
    EXPECT_EQ(shown.materials.images.size(), 1u);
    EXPECT_TRUE(anyMessage(session, "Materials: ", StatusMessage::Kind::Info)); // the KTX2 body
    // An edit of the same avatar shares its scan: the materials stay.
    EXPECT_FALSE(refreshViewMaterials(shown, edit::setTarget(document, 1), session));

    test::TexturedAvatarOptions huge;
    huge.claimedSize = 50000;
    write(folder / "huge.glb", test::texturedAvatar(huge));
    const Document hugeDocument = documentFromAvatar(loadDocumentAvatar(folder / "huge.glb", ""), {});
    EXPECT_TRUE(refreshViewMaterials(shown, hugeDocument, session));
    EXPECT_FALSE(shown.any());
    EXPECT_TRUE(
        anyMessage(session, "huge.glb: images/0: declares 50000 x 50000 pixels", StatusMessage::Kind::Error));
    std::filesystem::remove_all(folder);
}

} // namespace
} // namespace vl::ui
