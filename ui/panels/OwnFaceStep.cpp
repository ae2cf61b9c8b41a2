// Deformation > Use my mesh...: the user's mesh is read and its landmarks suggested; this step shows
// each landmark with where it came from and how sure the finder is, lets the user move any of them
// in the mesh's (u,v) (here or by dragging its dot in the 3D view), and builds the face only when they
// confirm (edit::useOwnFace). Opening, each move and the build are undo steps; the face changes only
// on the build.
#include "ui/panels/OwnFaceStep.h"

#include "ui/panels/FileActions.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/session/EditorSession.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace vl::ui {

void OwnFaceStep::open() {
    files_.dialog().open("Use my mesh (with (u,v) on the face)", FileDialog::Mode::OpenFile,
                         {".obj", ".ply", ".wrl", ".vrml", ".glb", ".gltf"},
                         [this](const std::filesystem::path& path) {
                             session_.attempt("Use my mesh", [&] { session_.face().openOwnFace(path); });
                         });
}

bool OwnFaceStep::active() const {
    return session_.document().ownFace != nullptr;
}

void OwnFaceStep::draw() {
    // Held for the frame: a move below replaces the document.
    const std::shared_ptr<const OwnFaceCandidate> step = session_.document().ownFace;
    const OwnFaceCandidate& candidate = *step;
    sectionHeader("Use my mesh: confirm the landmarks");
    ImGui::TextWrapped("%s: %zu vertices, %zu triangles with (u,v), %zu UV islands", candidate.name.c_str(),
                       candidate.mesh->positions.size(), candidate.mesh->triangles.size(),
                       candidate.mesh->islandCount);
    for (const std::string& note : candidate.suggestion.notes) ImGui::TextDisabled("%s", note.c_str());
    ImGui::TextWrapped(
        "Each landmark is a point of your mesh's (u,v), shown as a dot on the mesh in the view: "
        "drag a dot over the surface or a value here to move it; right and left are the "
        "face's own (its right eye is on the viewer's left).");

    // One row per landmark: its name, u and v (two drags, each a control the GUI tests can find as
    // "u##<name>" and "v##<name>"), then where it came from and how sure the finder is.
    const float column = ImGui::CalcTextSize("mouth_corner_right ").x;
    const float dragWidth = std::max(60.0f, (ImGui::GetContentRegionAvail().x - column) * 0.28f);
    for (const face::Landmark landmark : face::allLandmarks()) {
        const face::FoundLandmark& found = candidate.landmarks()[landmark];
        const std::string name(toString(landmark));
        ImGui::TextUnformatted(name.c_str());
        Vec2 uv = found.uv;
        bool moved = false;
        for (int k = 0; k < 2; ++k) {
            ImGui::SameLine(column + static_cast<float>(k) * (dragWidth + 6.0f));
            ImGui::SetNextItemWidth(dragWidth);
            float value = static_cast<float>(uv[k]);
            const std::string label = (k == 0 ? "u##" : "v##") + name;
            if (ctl::DragFloat(label.c_str(), &value, 0.001f, -10.0f, 10.0f, "%.4f")) {
                uv[k] = value;
                moved = true;
            }
            endEditOnRelease(session_); // one undo step per drag
        }
        if (moved)
            session_.attempt("Place landmark", [&] { session_.face().placeOwnFaceLandmark(landmark, uv); });
        ImGui::SameLine();
        if (!found.found())
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.35f, 1.0f), "%s",
                               face::isRequired(landmark) ? "missing" : "-");
        else
            ImGui::TextDisabled("%s %3.0f%%", std::string(face::sourceName(found.source)).c_str(),
                                100.0 * found.confidence);
        if (found.found() && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", found.method.c_str());
    }

    const std::string missing = candidate.missingRequired();
    if (!missing.empty()) ImGui::TextWrapped("Still missing: %s", missing.c_str());
    if (ctl::Button("Build face from these landmarks"))
        session_.attempt("Use my mesh", [&] { session_.face().buildOwnFace(); });
    ImGui::SameLine();
    if (ctl::Button("Cancel##ownface")) session_.face().cancelOwnFace();
}

nlohmann::json OwnFaceStep::probe() const {
    const auto& step = session_.document().ownFace;
    if (!step) return nullptr;
    nlohmann::json landmarks = nlohmann::json::object();
    for (const face::Landmark landmark : face::allLandmarks()) {
        const face::FoundLandmark& found = step->landmarks()[landmark];
        landmarks[std::string(toString(landmark))] = {
            {"source", face::sourceName(found.source)}, {"u", found.uv[0]}, {"v", found.uv[1]}};
    }
    return {{"file", step->file.string()}, {"missing", step->missingRequired()}, {"landmarks", landmarks}};
}

} // namespace vl::ui
