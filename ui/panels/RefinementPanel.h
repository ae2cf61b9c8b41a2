#pragma once
// Refinement panel: the adaptive mesh's criterion and thresholds, refine / simplify / re-adapt on a
// worker, the last run's counts, the automatic mode and the face's parameter sliders.
#include "ui/panels/PanelContext.h"

namespace vl::ui {

class RefinementPanel : public SidePanel {
  public:
    explicit RefinementPanel(const PanelContext& context) : session_(context.session) {}
    void draw() override;
    void addProbe(nlohmann::json& summary) const override;

  private:
    EditorSession& session_;
};

} // namespace vl::ui
