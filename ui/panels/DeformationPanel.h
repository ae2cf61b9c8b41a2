#pragma once
// Deformation panel: the face's base geometry (bundled, retargeted, the user's mesh), its parameter
// sliders and presets, and editing of the analytic influence regions, drawn on the face and in the
// (u,v) inset over the view.
#include "ui/panels/LandmarkHandles.h"
#include "ui/panels/OwnFaceStep.h"
#include "ui/panels/PanelContext.h"
#include "ui/panels/StoreSlidersSection.h"

#include <imgui.h>

#include <memory>
#include <string>

namespace vl {
struct DeformationCascade;
}

namespace vl::ui {

class DeformationPanel : public SidePanel {
  public:
    explicit DeformationPanel(const PanelContext& context)
        : session_(context.session), files_(context.files), ownFace_(context), handles_(context.session),
          storeSliders_(context) {}
    void draw() override;
    void addProbe(nlohmann::json& summary) const override;
    void documentReplaced() override { selected_ = {}; }

    // The analytic field being edited: an influence of a cascade stage (stage -1: none).
    struct Field {
        int stage = -1, influence = 0;
    };
    Field selectedField() const { return selected_; }
    // Selects the first analytic region of the cascade stage with this name.
    bool selectField(const std::string& stageName);
    bool showInfluence() const { return showInfluence_; }

    // The (u,v) inset over the face view: a title bar that moves it and the square (u,v) domain,
    // clipped to its frame. Where it sits is known before the view is drawn, so the view leaves
    // the inset's drags alone.
    struct InsetPlace {
        ImVec2 min, max; // the whole inset, title bar included
        float side = 0.0f, titleHeight = 0.0f;
        ImVec2 offsetMin, offsetMax; // the offsets that keep it inside the view
    };
    InsetPlace insetPlace(ImVec2 viewMin, ImVec2 viewMax) const;
    void inset(const InsetPlace& place); // of the selected field
    LandmarkHandles& landmarkHandles() { return handles_; }

  private:
    void uvView(float side);

    EditorSession& session_;
    FileActions& files_;
    OwnFaceStep ownFace_;
    LandmarkHandles handles_; // the step's landmarks as dots in the view
    StoreSlidersSection storeSliders_;
    std::shared_ptr<const DeformationCascade> ownFaceCascade_; // the cascade ownFaceLoaded_ was found for
    bool ownFaceLoaded_ = false;                               // the face is built from a user's mesh
    bool showInfluence_ = true;
    Field selected_;
    // The inset's top-left corner relative to its default place, the view's lower right (moved by
    // dragging its title bar; kept inside the view).
    ImVec2 insetOffset_{0.0f, 0.0f};
};

} // namespace vl::ui
