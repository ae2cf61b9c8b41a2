#pragma once
// Export panel: project save/load, the runtime exports of the core, the avatar's export and imports.
#include "ui/panels/AvatarPanel.h"
#include "ui/panels/PanelContext.h"

namespace vl::ui {

class ExportPanel : public SidePanel {
  public:
    ExportPanel(const PanelContext& context, AvatarPanel& avatar)
        : session_(context.session), files_(context.files), avatar_(avatar) {}
    void draw() override;

  private:
    EditorSession& session_;
    FileActions& files_;
    AvatarPanel& avatar_;
};

} // namespace vl::ui
