#pragma once
// Visemes panel: the viseme list (frequency, group after reduction), preview on click, loading and
// importing meshes, the avatar's section, and authoring of the selected viseme.
#include "ui/panels/AvatarPanel.h"
#include "ui/panels/PanelContext.h"
#include "ui/panels/VisemeAuthoring.h"
#include "ui/panels/VisemeSculptor.h"

#include <string>

namespace vl::ui {

class VisemesPanel : public SidePanel {
  public:
    // `view`: the view the sculptor works in (its camera aims the brush).
    VisemesPanel(const PanelContext& context, AvatarPanel& avatar, const Viewport& view)
        : session_(context.session), files_(context.files), speech_(context.speech), avatar_(avatar),
          authoring_(context), sculptor_(context.session, view) {}
    void draw() override;
    void addProbe(nlohmann::json& summary) const override {
        authoring_.addProbe(summary);
        summary["sculpt"] = sculptor_.probe();
    }
    void documentReplaced() override { importError_.clear(); }
    VisemeSculptor& sculptor() { return sculptor_; }

  private:
    void importSection(); // a mesh as a new viseme, or glTF morph targets as the visemes

    EditorSession& session_;
    FileActions& files_;
    SpeechPlayer& speech_;
    AvatarPanel& avatar_;
    VisemeAuthoring authoring_;
    VisemeSculptor sculptor_;
    std::string importName_;
    std::string importError_; // the core's message for the last failed import
};

} // namespace vl::ui
