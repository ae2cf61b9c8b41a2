#pragma once
// Deformation > Use my mesh...: the user's mesh is read and its landmarks suggested; this step shows
// each landmark, lets the user move it in the mesh's (u,v) and builds the face only on confirmation.
#include "core/document/OwnFace.h"
#include "ui/panels/PanelContext.h"

#include <optional>

namespace vl::ui {

class OwnFaceStep {
  public:
    explicit OwnFaceStep(const PanelContext& context) : session_(context.session), files_(context.files) {}
    void open(); // a file dialog for the mesh
    bool active() const { return candidate_.has_value(); }
    void draw(); // while active
    nlohmann::json probe() const;

  private:
    EditorSession& session_;
    FileActions& files_;
    std::optional<OwnFaceCandidate> candidate_; // the mesh whose landmarks await confirmation
};

} // namespace vl::ui
