#pragma once
// Frequencies panel: the phoneme -> viseme map (PhonemeMapEditor) or direct viseme frequencies, the
// resulting viseme frequencies live, loading a table, saving it as CSV, counting a corpus.
#include "ui/panels/PanelContext.h"
#include "ui/panels/PhonemeMapEditor.h"

namespace vl::ui {

class FrequenciesPanel : public SidePanel {
  public:
    explicit FrequenciesPanel(const PanelContext& context)
        : session_(context.session), files_(context.files), mapEditor_(context) {}
    void draw() override;
    void addProbe(nlohmann::json& summary) const override { mapEditor_.addProbe(summary); }
    // Opens the map editor's assignment from a bundled map id ("oculus", ...) or "per-phoneme".
    void startMapFrom(const std::string& id) { mapEditor_.startFrom(id); }

  private:
    EditorSession& session_;
    FileActions& files_;
    PhonemeMapEditor mapEditor_;
};

} // namespace vl::ui
