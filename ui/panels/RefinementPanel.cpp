// Refinement panel: the adaptive mesh's criterion and thresholds, refine / simplify / re-adapt
// buttons running on a worker thread, live counts and timing, the automatic mode, and the face's
// parameter sliders (the same as the Deformation panel's: the view shows the face at them).
#include "ui/panels/RefinementPanel.h"
#include "ui/UiScale.h"

#include "core/document/Document.h"
#include "core/face/FaceDomain.h"
#include "core/inspect/DistanceUnits.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/panels/ParameterSliders.h"
#include "ui/session/EditorSession.h"
#include "ui/widgets/Controls.h"
#include "ui/widgets/JobProgress.h"

#include <imgui.h>

#include <cstdio>
#include <string>

namespace vl::ui {
namespace {

// A slider format showing a model-unit value and its length in mm ("%.4f (0.20 mm)").
std::string withMillimetres(float value, double millimetresPerUnit) {
    char text[64];
    std::snprintf(text, sizeof text, "%%.4f (%.2f mm)", static_cast<double>(value) * millimetresPerUnit);
    return text;
}

} // namespace

void RefinementPanel::draw() {
    const FaceModel& model = session_.document().face;
    if (!model.cascade) {
        ImGui::TextWrapped("Adaptive refinement works on the deformable face.");
        if (ctl::Button("Load bundled face")) session_.attempt("Load face", [&] { session_.face().load(); });
        return;
    }
    CriterionSettings settings = session_.document().refinement;
    bool changed = false;
    sectionHeader("Criterion");
    int kind = static_cast<int>(settings.kind);
    bool criterionChanged = ctl::RadioButton("depth", &kind, 0);
    ImGui::SameLine();
    criterionChanged |= ctl::RadioButton("normals", &kind, 1);
    ImGui::SameLine();
    criterionChanged |= ctl::RadioButton("contour error", &kind, 2);
    changed |= criterionChanged;
    settings.kind = static_cast<CriterionKind>(kind);
    ImGui::PushItemWidth(scaled(-150.0f));
    changed |= ctl::SliderInt("max depth", &settings.maxDepth, 0, 16, "%d levels");
    endEditOnRelease(session_);
    switch (settings.kind) {
    case CriterionKind::Depth:
        changed |= ctl::SliderInt("uniform depth", &settings.depth.depth, 0, 12, "%d levels");
        endEditOnRelease(session_);
        break;
    case CriterionKind::Normals: {
        float dihedral = static_cast<float>(settings.normals.dihedralAngleDeg);
        float normal = static_cast<float>(settings.normals.normalAngleDeg);
        if (ctl::SliderFloat("dihedral angle", &dihedral, 1.0f, 90.0f, "%.1f deg")) {
            settings.normals.dihedralAngleDeg = dihedral;
            changed = true;
        }
        endEditOnRelease(session_);
        if (ctl::SliderFloat("normal angle", &normal, 1.0f, 90.0f, "%.1f deg")) {
            settings.normals.normalAngleDeg = normal;
            changed = true;
        }
        endEditOnRelease(session_);
        break;
    }
    case CriterionKind::Contour: {
        // The errors are distances in the face's model units: shown with their length in mm.
        float average = static_cast<float>(settings.contour.averageError);
        float maximum = static_cast<float>(settings.contour.maximumError);
        const double mm = guessMillimetresPerUnit(session_.face().samples().rest);
        const std::string averageFormat = withMillimetres(average, mm);
        const std::string maximumFormat = withMillimetres(maximum, mm);
        if (ctl::SliderFloat("average error", &average, 0.001f, 0.5f, averageFormat.c_str(),
                             ImGuiSliderFlags_Logarithmic)) {
            settings.contour.averageError = average;
            changed = true;
        }
        endEditOnRelease(session_);
        if (ctl::SliderFloat("maximum error", &maximum, 0.001f, 2.0f, maximumFormat.c_str(),
                             ImGuiSliderFlags_Logarithmic)) {
            settings.contour.maximumError = maximum;
            changed = true;
        }
        endEditOnRelease(session_);
        changed |= ctl::SliderInt("samples per side", &settings.contour.samplesPerSide, 1, 16, "%d per edge");
        endEditOnRelease(session_);
        break;
    }
    }
    ImGui::PopItemWidth();
    if (changed) session_.attempt("Thresholds", [&] { session_.face().setRefinementSettings(settings); });
    if (criterionChanged) session_.history().endEdit(); // a criterion switch is its own undo step

    sectionHeader("Adapt the face mesh");
    const bool busy = session_.face().refinementRunning();
    if (busy) ImGui::BeginDisabled();
    if (ctl::Button("Refine"))
        session_.attempt("Refine", [&] { session_.face().startRefinement(RefineAction::Refine); });
    ImGui::SameLine();
    if (ctl::Button("Simplify"))
        session_.attempt("Simplify", [&] { session_.face().startRefinement(RefineAction::Simplify); });
    ImGui::SameLine();
    if (ctl::Button("Re-adapt"))
        session_.attempt("Re-adapt", [&] { session_.face().startRefinement(RefineAction::Adapt); });
    ImGui::SameLine();
    if (ctl::Button("For all visemes"))
        session_.attempt("Refine", [&] { session_.face().startRefinement(RefineAction::AllVisemes); });
    if (busy) ImGui::EndDisabled();
    helpMarker(
        "Refine splits edges where the criterion asks (for the current slider values); Simplify welds "
        "where it allows; Re-adapt does both after a change. 'For all visemes' refines one mesh for "
        "every viseme pose: Generate viseme set (Deformation panel) then gives an interpolable set on it.");
    if (bool automatic = session_.face().autoRefine();
        ctl::Checkbox("Automatic: re-adapt after every slider or threshold change", &automatic))
        session_.face().setAutoRefine(automatic);
    // The progress line is always there and the run's report is below the sliders: a run that
    // starts or ends (Automatic ticked) moves no control under the cursor. While a run lasts the line
    // shows its progress and Cancel.
    bool shown = false;
    for (const auto& job : session_.jobs().running())
        if (job.job == SessionJobs::Job::Refinement) {
            shown = true;
            if (jobProgress(job.label, job.fraction, job.secondsLeft, "Cancel##refinement", -1))
                session_.jobs().cancel(job.job);
        }
    if (!shown) ImGui::ProgressBar(0.0f, ImVec2(-1, 0), "no refinement running");

    sectionHeader("Parameters");
    noteText("The view shows the refined skin and, inside it, the head's parts (eyeballs, teeth, tongue, "
             "mouth cavity) at these values.");
    parameterSliders(session_);

    sectionHeader("Current mesh");
    ImGui::Text("%zu vertices, %zu triangles", model.domain->positions.size(),
                model.domain->triangles.size());
    if (const auto& report = session_.face().lastRefinement()) {
        ImGui::Text("Last run: %s in %.1f ms", report->action.c_str(), report->milliseconds);
        // The counts a designer asks about: how big the mesh was and is, and what each way did. An
        // edge split adds one vertex, a weld removes one.
        ImGui::Text("Vertices: %zu before, %zu now", report->verticesBefore, report->vertices);
        if (report->fromBaseMesh)
            ImGui::TextWrapped("Started again from the %zu-vertex base mesh (a new face or field).",
                               report->verticesAtStart);
        else if (report->stats.rebuilt)
            ImGui::TextWrapped("Refined again from the base mesh: the change reached most of the face, "
                               "where that is quicker than re-adapting.");
        ImGui::Text("Refined: %zu vertices added (edge splits)", report->stats.splits);
        ImGui::Text("Coarsened: %zu vertices removed (welds)", report->stats.welds);
        ImGui::TextDisabled("Triangles: %zu before, %zu after; %zu refinement tests", report->trianglesBefore,
                            report->triangles, report->stats.tests);
        if (report->maxLevel >= 0) ImGui::Text("Deepest level: %d", report->maxLevel);
    }
    shownNote_ = meshNote(*model.domain, domainRefined(), session_.face().lastRefinement().has_value());
    ImGui::TextWrapped("%s", shownNote_.c_str());
}

bool RefinementPanel::domainRefined() {
    const auto& domain = session_.document().face.domain;
    if (domain != checkedDomain_) {
        checkedDomain_ = domain;
        checkedRefined_ = domain && isRefinedDomain(*domain);
    }
    return checkedRefined_;
}

bool RefinementPanel::isRefinedDomain(const MeshData& domain) {
    // Regular: the base mesh a face gets when it is loaded (in the editor or from a project without
    // a refined mesh); anything else is a refinement's.
    const auto regular = [&](int resolution) {
        const MeshData base = face::faceDomainMesh(resolution, face::DomainDensity::MouthFocused);
        return base.uvs == domain.uvs && base.triangles == domain.triangles;
    };
    return !regular(kFaceDomainResolution) && !regular(SessionFace::kEditorResolution);
}

std::string RefinementPanel::meshNote(const MeshData& domain, bool refined, bool ranSinceOpened) {
    const std::string size = std::to_string(domain.positions.size()) + " vertices";
    if (!refined) return "The face is shown on its regular base mesh (" + size + ") until you refine it.";
    if (ranSinceOpened) return "The face is shown on the refined mesh (" + size + ").";
    // Reopened: the project's refined mesh is restored; no run is needed to see it.
    return "The face is shown on the refined mesh saved with the project (" + size +
           "); no refinement run since it was opened.";
}

void RefinementPanel::addProbe(nlohmann::json& summary) const {
    // The counts of the last run, as the panel states them.
    nlohmann::json refine;
    if (const auto& report = session_.face().lastRefinement())
        refine = {{"vertices_before", report->verticesBefore},
                  {"vertices_at_start", report->verticesAtStart},
                  {"from_base_mesh", report->fromBaseMesh},
                  {"vertices_after", report->vertices},
                  {"added", report->stats.splits},
                  {"removed", report->stats.welds}};
    summary["refine"] = std::move(refine);
    summary["refine_mesh_note"] = shownNote_;
}

} // namespace vl::ui
