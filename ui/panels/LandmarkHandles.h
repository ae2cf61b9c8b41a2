#pragma once
// The own-face step's landmarks on the user's mesh in the main view (Deformation > Use my mesh...):
// each a labelled dot, highlighted with its name and origin in a tooltip under the cursor, dragged
// over the surface with the left button (ui/session/LandmarkDrag.h: the release is one undo step).
// View state only: the landmarks are the document's (Document::ownFace), as the panel's fields show.
#include "ui/render/Camera.h"
#include "ui/render/Viewport.h"
#include "ui/session/LandmarkDrag.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <optional>

namespace vl::ui {

class EditorSession;

class LandmarkHandles {
  public:
    explicit LandmarkHandles(EditorSession& session) : session_(session), drag_(session) {}

    // Before the view is drawn over [min, min + size]: whether the left button is the handles'
    // (a dot under the cursor or a drag under way), so that the view does not orbit with it.
    bool wantsMouse(const OrbitCamera& camera, ImVec2 min, ImVec2 size);
    // After the view was drawn: the dots and labels, hover and drag.
    void handle(const OrbitCamera& camera, const ViewportEvents& events);
    // The dots where they were drawn (screen pixels), the hovered and the dragged landmark.
    nlohmann::json probe() const;

  private:
    // The landmark whose dot lies within reach of `mouse`, nearest first.
    std::optional<face::Landmark> under(const OrbitCamera& camera, ImVec2 min, ImVec2 max,
                                        ImVec2 mouse) const;

    EditorSession& session_;
    LandmarkDrag drag_;
    std::optional<face::Landmark> hovered_;
    nlohmann::json drawn_ = nlohmann::json::object();
};

} // namespace vl::ui
