// Avatars in the editor: File > Import avatar... opens a glTF/GLB/VRM as a document (its visemes over
// every mesh carrying them), the Visemes panel shows the avatar's meshes and the target pattern that
// selects the visemes, the views show the meshes without visemes as context (in their materials or greyed),
// and File > Export avatar... writes the same avatar with its visemes reduced. The work is the core's
// (core/document/AvatarDocument.h).
#include "ui/panels/AvatarPanel.h"
#include "core/gltf/AvatarReport.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/Gltfpack.h"
#include "ui/UiScale.h"
#include "ui/panels/FileActions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

namespace vl::ui {

void AvatarPanel::openImport() {
    files_.guarded([this] {
        files_.dialog().open(
            "Import avatar", FileDialog::Mode::OpenFile, {".glb", ".gltf", ".vrm"}, [this](const auto& path) {
                session_.attempt("Import avatar", [&] { session_.files().startImportAvatar(path); });
            });
    });
}

void AvatarPanel::openExport() {
    const DocumentAvatar& avatar = session_.document().avatar;
    if (!avatar.isSet()) {
        session_.error("Export avatar: the document has no avatar: use File > Import avatar... first");
        return;
    }
    std::string extension = avatar.file.extension().string();
    if (extension != ".vrm") extension = ".glb";
    SessionFiles::AvatarExport options;
    options.write.names = names_ == 1 ? AvatarNames::Merged : AvatarNames::Original;
    options.write.targetNormals = targetNormals_;
    options.gltfpack = gltfpackChosen();
    files_.dialog().open(
        "Export avatar", FileDialog::Mode::SaveFile, {".glb", ".vrm"},
        [this, options](const auto& path) {
            session_.attempt("Export avatar", [&] { session_.files().startExportAvatar(path, options); });
        },
        avatar.file.stem().string() + "_reduced" + extension);
}

void AvatarPanel::visemesSection() {
    const DocumentAvatar& avatar = session_.document().avatar;
    const AvatarScan& scan = *avatar.scan;
    if (patternScan_ != avatar.scan) { // a new avatar, an applied pattern, an undo
        pattern_ = avatar.pattern;
        if (patternScan_ && meshRow_ >= static_cast<int>(scan.meshes.size())) meshRow_ = -1;
        patternScan_ = avatar.scan;
    }
    sectionHeader("Avatar");
    ImGui::TextWrapped("%s", avatar.file.filename().string().c_str());
    ImGui::Text("%zu meshes, %zu vertices in the file; %zu visemes selected by %s", scan.meshes.size(),
                scan.fileVertices, scan.visemes.size(), scan.selection.c_str());

    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("Viseme targets");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(scaled(200.0f));
    const bool entered = ctl::InputTextWithHint("##avatar-pattern", "Oculus viseme names", &pattern_,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ctl::Button("Apply pattern") || entered)
        session_.attempt("Viseme targets", [&] { session_.authoring().setAvatarPattern(pattern_); });
    helpMarker("A glob over the morph target names, case-insensitive: * any text, ? one character, [AIUEO] "
               "one of, e.g. Fcl_MTH_[AIUEO] for VRoid, V_* for Character Creator. Empty: the Oculus visemes "
               "(viseme_sil ... viseme_U, with or without the prefix). Other targets (ARKit, expressions) "
               "are kept as they are.");

    // The import report, mesh by mesh: a row selects the mesh whose targets are listed below.
    if (ImGui::BeginTable("##avatar-meshes", 5,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV |
                              ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("Mesh", ImGuiTableColumnFlags_WidthStretch, 2.0f);
        ImGui::TableSetupColumn("Primitives", ImGuiTableColumnFlags_WidthStretch, 0.8f);
        ImGui::TableSetupColumn("Vertices", ImGuiTableColumnFlags_WidthStretch, 0.9f);
        ImGui::TableSetupColumn("Visemes", ImGuiTableColumnFlags_WidthStretch, 0.8f);
        ImGui::TableSetupColumn("Other targets", ImGuiTableColumnFlags_WidthStretch, 1.1f);
        ImGui::TableHeadersRow();
        for (std::size_t row = 0; row < scan.meshes.size(); ++row) {
            const AvatarMesh& mesh = scan.meshes[row];
            std::size_t vertices = 0, visemes = 0;
            for (const AvatarPrimitive& primitive : mesh.primitives) vertices += primitive.vertices;
            for (const AvatarTarget& target : mesh.targets) visemes += target.viseme >= 0 ? 1 : 0;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            const std::string name = (mesh.name.empty() ? "mesh " + std::to_string(mesh.index) : mesh.name) +
                                     (mesh.carriesVisemes ? "" : " (context)") + "##avatar-mesh" +
                                     std::to_string(row);
            if (!mesh.carriesVisemes)
                ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
            // The first column only (not spanning the row): a table clips each column on its own.
            if (ctl::Selectable(name.c_str(), meshRow_ == static_cast<int>(row)))
                meshRow_ = static_cast<int>(row);
            if (!mesh.carriesVisemes) ImGui::PopStyleColor();
            ImGui::TableNextColumn();
            ImGui::Text("%zu", mesh.primitives.size());
            ImGui::TableNextColumn();
            ImGui::Text("%zu", vertices);
            ImGui::TableNextColumn();
            ImGui::Text("%zu", visemes);
            ImGui::TableNextColumn();
            ImGui::Text("%zu", mesh.targets.size() - visemes);
        }
        ImGui::EndTable();
    }
    if (meshRow_ >= 0 && static_cast<std::size_t>(meshRow_) < scan.meshes.size())
        ImGui::TextWrapped("%s", meshReport().c_str());
    else
        ImGui::TextDisabled("Click a mesh for its primitives and which targets are visemes (and why the "
                            "others are not).");
}

std::string AvatarPanel::meshReport() const {
    const DocumentAvatar& avatar = session_.document().avatar;
    if (!avatar.isSet() || meshRow_ < 0 || static_cast<std::size_t>(meshRow_) >= avatar.scan->meshes.size())
        return {};
    return formatAvatarMeshReport(avatar.scan->meshes[static_cast<std::size_t>(meshRow_)]);
}

void AvatarPanel::exportSection() {
    sectionHeader("Avatar (the same avatar, visemes reduced)");
    ImGui::TextWrapped("Every mesh, skin, material, animation and extension is kept; the viseme targets of "
                       "%s become the m keys.",
                       session_.document().avatar.file.filename().string().c_str());
    ImGui::TextUnformatted("Target names:");
    ImGui::SameLine();
    ctl::RadioButton("original (every viseme name stays)", &names_, 0);
    ImGui::SameLine();
    ctl::RadioButton("merged (one target per key)", &names_, 1);
    ctl::Checkbox("normals of the keys (NORMAL/TANGENT displacements)", &targetNormals_);
    gltfpackOption();
    if (ctl::Button("Export avatar...", ImVec2(scaled(200), 0))) openExport();
    ImGui::SameLine();
    noteText("a .glb (or .vrm), never the file it was read from");
    // What the last export wrote, read back from the file: a runtime drives these targets.
    if (const auto& lines = session_.files().lastAvatarExport(); !lines.empty()) {
        ImGui::TextUnformatted("Last export, which target carries which key:");
        for (const std::string& line : lines) {
            ImGui::Bullet();
            ImGui::TextWrapped("%s", line.c_str()); // long member lists wrap instead of running off
        }
    }
}

// Re-compression offered where it can run: gltfpack found, and not a VRM (gltfpack renumbers what
// the VRM extension addresses). Checked by default when the avatar came in compressed, so a
// compressed avatar goes out compressed unless the designer says otherwise.
void AvatarPanel::gltfpackOption() {
    const DocumentAvatar& avatar = session_.document().avatar;
    if (!gltfpackSearched_) {
        gltfpackPath_ = findGltfpack();
        gltfpackSearched_ = true;
    }
    const bool vrm = avatar.file.extension() == ".vrm";
    const bool available = !gltfpackPath_.empty() && !vrm;
    bool chosen = gltfpackChosen();
    ImGui::BeginDisabled(!available);
    if (ctl::Checkbox("re-compress with gltfpack (meshopt + quantised, like real exporters)", &chosen))
        gltfpack_ = chosen ? 1 : 0;
    ImGui::EndDisabled();
    if (vrm)
        noteText("not for a VRM: gltfpack renumbers the nodes and meshes its extension refers to");
    else if (gltfpackPath_.empty())
        noteText((std::string("gltfpack not found: ") + kGltfpackHint).c_str());
    else if (avatarStoredCompressed(*avatar.scan))
        noteText("the avatar was read compressed; without this its keys are written as plain floats");
}

bool AvatarPanel::gltfpackChosen() const {
    const DocumentAvatar& avatar = session_.document().avatar;
    if (!avatar.isSet() || gltfpackPath_.empty() || avatar.file.extension() == ".vrm") return false;
    return gltfpack_ < 0 ? avatarStoredCompressed(*avatar.scan) : gltfpack_ == 1;
}

void AvatarPanel::addProbe(nlohmann::json& summary) const {
    // The file, its pattern, the meshes shown and greyed.
    const Document& document = session_.document();
    const DocumentAvatar& avatar = document.avatar;
    nlohmann::json shown = nullptr;
    if (avatar.isSet()) {
        nlohmann::json meshes = nlohmann::json::array();
        for (const AvatarMesh& mesh : avatar.scan->meshes)
            meshes.push_back({{"name", mesh.name}, {"visemes", mesh.carriesVisemes}});
        shown = {{"file", avatar.file.string()},
                 {"pattern", avatar.pattern},
                 {"added_rest", avatar.scan->addedRest},
                 {"visemes", visemeNames(document)},
                 {"meshes", std::move(meshes)},
                 {"viseme_vertices", document.visemes->vertexCount()},
                 {"greyed_vertices", avatar.scan->context.positions.size()}};
    }
    summary["avatar"] = std::move(shown);
    summary["avatar_mesh_report"] = meshReport();
    summary["avatar_gltfpack"] = gltfpackChosen();
}

} // namespace vl::ui
