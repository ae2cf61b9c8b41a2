#pragma once
// The editor's 3D views: the main view (the visemes, or the face with the (u,v) inset of the
// Deformation panel; the Weights panel paints in it) and the Reduction panel's side-by-side
// comparison with the Say timeline under it. Owns the GPU copies of the session's meshes, the
// cameras (one per subject, kept across tabs) and the per-vertex scalars they show; asks the
// panels what to show.
#include "ui/panels/DeformationPanel.h"
#include "ui/panels/Panel.h"
#include "ui/panels/ReductionPanel.h"
#include "ui/panels/SpeechPlayer.h"
#include "ui/panels/VisemesPanel.h"
#include "ui/panels/WeightsPanel.h"
#include "ui/render/GlShader.h"
#include "ui/render/GpuMesh.h"
#include "ui/render/Viewport.h"
#include "ui/session/EditorSession.h"
#include "ui/session/ViewMaterials.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vl::ui {

// What the main view shows.
enum class ViewSubject { Visemes, Face };

class EditorViews {
  public:
    // The panels whose state the views show (they may be constructed after the views).
    struct Panels {
        VisemesPanel& visemes;
        WeightsPanel& weights;
        DeformationPanel& deformation;
        ReductionPanel& reduction;
    };
    EditorViews(EditorSession& session, SpeechPlayer& speech, Panels panels);

    // Once per frame before drawing: the GPU copies of what changed, new meshes framed.
    void update(Panel active);
    void draw(Panel active, float left, float top, float width, float height);
    void frameAll(); // every view on its model (key F, Home)
    // A new document: both subjects' cameras framed on what it shows.
    void documentReplaced() { frameVisemes_ = frameFace_ = true; }
    // The shown subject's camera (one for both comparison views: they stay linked) from a side
    // (numpad 1/3/7), back to the front view framed (View > Reset view), or switched between
    // perspective and orthographic (numpad 5).
    void setView(StandardView view);
    void resetView();
    void toggleOrthographic();
    void zoom(float factor) { shownCamera().zoom(factor); }
    bool orthographic() const { return shownCamera().orthographic; }
    // Start options: both subjects' cameras from that side, orthographic or not.
    void setStartView(StandardView view, bool orthographic);
    const Viewport& mainView() const { return mainView_; }
    // The status bar's statistics of what the views show.
    std::string statistics() const;
    // The face view's last frame, the camera and the wireframe, for the GUI probe.
    void addProbe(nlohmann::json& summary) const;

    bool wireframe = true;
    // Materials or error colours (View menu, the switch in the views' corner); only documents with
    // materials show the choice, the others always draw their analysis colours.
    SurfaceShading surface = SurfaceShading::Materials;
    bool hasMaterials() const { return materials_.any(); }
    SurfaceShading shownSurface() const { return hasMaterials() ? surface : SurfaceShading::ErrorColours; }
    // Sets `surface`; the Reduction panel's right view follows (error colours, or skin in materials).
    void setSurface(SurfaceShading shading);

  private:
    void drawMainView(ImVec2 size);
    // The own-face step: the user's mesh with its landmarks as draggable dots.
    ViewportEvents drawOwnFaceStep(ImVec2 size, const DrawStyle& style, std::string& label);
    void comparisonViews(ImVec2 size);
    void frameNewMeshes();
    void syncGpu();
    void syncContextMesh();
    void updateScalars();
    void drawContext(const glm::mat4& view, const glm::mat4& projection) const;
    std::vector<float> visemeWeights(int viseme) const;
    // The face parameters that pose the head's parts for viseme weights of a set the face made
    // (q0 + sum_i w_i (q_i - q0), q0 the neutral's); empty when the set is not the face's.
    std::vector<float> visemePartWeights(std::span<const float> weights);
    // The head's parts (eyeballs, teeth, tongue, mouth cavity) inside the skin at face parameters q,
    // in their own colours: the face view and the viseme view draw them alike. Returns the triangles.
    std::size_t drawHeadParts(std::span<const float> q, const glm::mat4& view, const glm::mat4& projection,
                              const DrawStyle& skinStyle) const;
    ColorMode surfaceColours() const; // face colours for visemes generated from the face model
    // What a skin-coloured drawing of `mesh` shows: its materials when they are drawnSurface_.
    ColorMode skinColours(const GpuMesh& mesh) const;
    // The merge error of viseme `selected` per vertex in [0,1] (and errorLegendMax_); false without
    // a reduced model.
    bool mergeErrors(int selected, std::vector<float>& values);
    // The Materials | Error colours switch in the corner of a view about to be shown at `viewMin`.
    void excludeSurfaceSwitch(Viewport& view, ImVec2 viewMin, ImVec2 size) const;
    void surfaceSwitch(const ViewportEvents& view);
    void errorLegend(const ViewportEvents& view) const; // the merge error's colour ramp in mm
    nlohmann::json faceViewProbe() const;
    void viewLabel(const ViewportEvents& view, const std::string& text); // its title, kept for the probe
    OrbitCamera& shownCamera() { return subject_ == ViewSubject::Face ? faceCamera_ : visemeCamera_; }
    const OrbitCamera& shownCamera() const {
        return subject_ == ViewSubject::Face ? faceCamera_ : visemeCamera_;
    }

    EditorSession& session_;
    SpeechPlayer& speech_;
    Panels panels_;
    Panel active_ = Panel::Visemes;
    ViewSubject subject_ = ViewSubject::Visemes;
    GlShader shader_;
    GpuMesh visemeMesh_;  // neutral + one target per viseme
    GpuMesh mergedMesh_;  // neutral + one target per merged group
    GpuMesh faceMesh_;    // face cascade at q = 0 + one target per parameter
    GpuMesh partsMesh_;   // the head's parts (eyeballs, teeth, tongue, cavity) in the same form
    GpuMesh contextMesh_; // an avatar's meshes without visemes, drawn greyed
    GpuMesh ownFaceMesh_; // the user's mesh while its landmarks are placed (Use my mesh...)
    Viewport mainView_, beforeView_, afterView_;
    std::uint64_t uploadedGeometry_ = 0;
    // Caches hold what they show (shared, immutable) or its revision, never a bare address that a
    // later allocation could reuse.
    std::uint64_t uploadedFace_ = 0; // SessionFace::samplesRevision of the face mesh's upload
    bool uploadedFaceShown_ = false; // that upload had a face (framed when one appears)
    std::shared_ptr<const HeadPartSamples> uploadedParts_; // what partsMesh_ holds
    std::shared_ptr<const AvatarScan> uploadedContext_;    // the scan contextMesh_ shows
    std::shared_ptr<const face::UvMesh> uploadedOwnFace_;  // the mesh ownFaceMesh_ shows
    std::uint64_t uploadedMergedCurve_ = 0;                // ReductionService::curveRevision()
    int uploadedMergedGroups_ = 0;
    // What each mesh's scalars currently show, to re-upload only on change.
    std::string weightsKey_, errorKey_, influenceKey_;
    std::string mainErrorKey_;    // the merge error on visemeMesh_'s scalars (Visemes panel, error colours)
    ViewMaterials materials_;     // of the document's set, uploaded on visemeMesh_, mergedMesh_, contextMesh_
    double errorLegendMax_ = 0.0; // largest weighted distance of the error colours, model units
    // What the face view drew in its last frame (for the probe): the panel, the weights, and the
    // triangles of skin and parts.
    struct ShownFace {
        Panel panel = Panel::Count;
        std::vector<float> weights;
        std::size_t skinTriangles = 0, partTriangles = 0;
    } shownFace_;
    // The parts the viseme view drew in its last frame (triangles; their face parameters).
    struct ShownVisemeParts {
        std::size_t triangles = 0;
        std::vector<float> q;
    } shownVisemeParts_;
    std::vector<std::string> shownLabels_;           // the views' titles this frame
    ColorMode shownMainColour_ = ColorMode::Surface; // how the main view drew the visemes last frame
    // What the views being drawn show (the comparison follows the Reduction panel's right view).
    SurfaceShading drawnSurface_ = SurfaceShading::ErrorColours;
    // The camera of each subject, kept across tabs; framed when its mesh first appears.
    OrbitCamera visemeCamera_, faceCamera_;
    std::vector<Vec3> framedNeutral_; // the neutral the viseme camera was last framed on
    bool frameVisemes_ = true, frameFace_ = true;
};

} // namespace vl::ui
