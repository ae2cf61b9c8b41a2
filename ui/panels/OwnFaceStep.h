#pragma once
// Deformation > Use my mesh...: the user's mesh is read and its landmarks suggested; this step shows
// each landmark, lets the user move it in the mesh's (u,v) and builds the face only on confirmation.
// The step and its landmarks are document state (Document::ownFace): the numeric fields here and the
// draggable dots in the 3D view (LandmarkHandles) read and edit the same landmarks.
#include "core/document/OwnFace.h"
#include "ui/panels/PanelContext.h"

namespace vl::ui {

class OwnFaceStep {
  public:
    explicit OwnFaceStep(const PanelContext& context) : session_(context.session), files_(context.files) {}
    void open();         // a file dialog for the mesh
    bool active() const; // the document has an own-face step open
    void draw();         // while active
    nlohmann::json probe() const;

  private:
    EditorSession& session_;
    FileActions& files_;
};

} // namespace vl::ui
