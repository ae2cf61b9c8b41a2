#pragma once
// The session's face facet: the deformable face as undoable edits (load, sliders, presets, fields,
// retargeting, the own-face step), its adaptive refinement on a worker thread, and what the views
// show of it (per-vertex samples, head parts), memoized by the face's revisions (DocumentInputs).
#include "core/document/Document.h"
#include "core/document/OwnFace.h"
#include "ui/session/FaceSamples.h"
#include "ui/session/RefinementService.h"
#include "ui/session/SessionCore.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

class SessionFace {
  public:
    explicit SessionFace(SessionCore& core);

    // Loads the face of `individual` (fields, parameters) on a (u,v) mesh of the given resolution.
    void load(face::Individual individual = face::Individual::Bundled, int resolution = kEditorResolution);
    void setParameter(int parameter, double value);
    void setParameters(std::vector<double> values, const std::string& actionName);
    // The parameter vector of a viseme of the face (its presets, by default oculusVisemes()).
    void applyVisemePreset(const std::string& viseme);
    // Replaces one analytic influence region of a stage (validated by the core first).
    void setInfluence(int stage, int influence, const InfluenceField& field);
    // Retargeting: the same fields on another individual's base geometry.
    void setIndividual(face::Individual individual);
    // The face's visemes generated on its (u,v) mesh become the viseme set (embedded meshes).
    void generateVisemes();

    // Per-vertex samples of the current cascade on its mesh (made once per cascade and mesh).
    const FaceSamples& samples();
    // Whether samples() has the current face's samples without evaluating the cascade (after a
    // refinement: the worker's own samples).
    bool samplesReady() const;
    // Changes when samples() does (the face's cascade or mesh): views re-upload when it differs.
    std::uint64_t samplesRevision() const { return core_.inputs().revision(kFacePart | kFaceMeshPart); }
    // The head's parts of the current face (eyeballs, teeth, tongue, mouth cavity; for a face built
    // from the user's mesh, the bundled parts carried to it) in morph form, shown beside the skin in
    // the face views. Made once per cascade: sliders move them through the morph weights, a field
    // edit, retargeting or another face makes them again; a refined skin keeps them. Null without a
    // face; empty (and said once in the status bar) when the face's landmarks carry no parts.
    std::shared_ptr<const HeadPartSamples> parts();

    // Own face (Deformation > Use my mesh...): the face built from the user's mesh and confirmed
    // landmarks becomes the document's face (one undo step); the status bar says what the build found.
    void useOwnFace(const OwnFaceCandidate& candidate);
    // The own-face step as document state (Document::ownFace), each change one undo step: open on a
    // mesh (its landmarks suggested), place a landmark at a (u,v) of the mesh (the calls of one
    // numeric drag merge into one step; endEdit() closes it), build from the step's landmarks
    // (useOwnFace above, closing the step) or cancel it.
    void openOwnFace(const std::filesystem::path& mesh);
    void placeOwnFaceLandmark(face::Landmark landmark, const Vec2& uv);
    void buildOwnFace();
    void cancelOwnFace();

    // --- adaptive refinement ---
    void setRefinementSettings(const CriterionSettings& settings); // validated, undoable
    // Runs on a worker thread; the refined (u,v) mesh becomes the face's display and viseme mesh.
    // Refused while a refinement runs.
    void startRefinement(RefineAction action) { refinement_.start(core_.document(), action, false); }
    bool refinementRunning() const { return refinement_.running(); }
    const std::optional<RefinementReport>& lastRefinement() const { return refinement_.last(); }
    // Re-adapt in the background after every parameter, field or threshold change (off by default).
    bool autoRefine() const { return autoRefine_; }
    void setAutoRefine(bool on) { autoRefine_ = on; }

    // For the session: collecting a finished refinement and starting automatic ones (once per
    // frame), the running job for the job list, waiting for the worker.
    void poll();
    RefinementService& refinement() { return refinement_; }
    const RefinementService& refinement() const { return refinement_; }

    // (u,v) resolution of a face loaded in the editor (finer than a project's, for live sliders).
    static constexpr int kEditorResolution = 48;

  private:
    void collectRefinement();
    SessionCore& core_;
    RefinementService refinement_;
    bool autoRefine_ = false;
    // samples() cache: the display samples of the face at samplesRevision_ (0: none), from the
    // refinement worker when it made that mesh, else computed on first use.
    std::shared_ptr<const FaceSamples> samples_;
    std::uint64_t samplesRevision_ = 0;
    // parts() cache: the parts of the cascade at partsRevision_ (revision(kFacePart)).
    std::shared_ptr<const HeadPartSamples> parts_;
    std::uint64_t partsRevision_ = 0;
};

} // namespace vl::ui
