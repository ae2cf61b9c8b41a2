#pragma once
// Weights panel: the metric's per-vertex weights (uniform, area, painted) and the paint tools
// (WeightPainter); the weight under the cursor shows beside it in the view.
#include "ui/panels/PanelContext.h"
#include "ui/panels/WeightPainter.h"

namespace vl::ui {

class WeightsPanel : public SidePanel {
  public:
    WeightsPanel(const PanelContext& context, const Viewport& view)
        : session_(context.session), painter_(context.session, view) {}
    void draw() override;
    void addProbe(nlohmann::json& summary) const override;

    WeightPainter& painter() { return painter_; }
    bool showColours() const { return showColours_; }

  private:
    EditorSession& session_;
    WeightPainter painter_;
    bool showColours_ = true; // the weights as colours on the mesh
};

} // namespace vl::ui
