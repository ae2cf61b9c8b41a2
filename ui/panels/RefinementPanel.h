#pragma once
// Refinement panel: the adaptive mesh's criterion and thresholds, refine / simplify / re-adapt on a
// worker, the last run's counts, the automatic mode and the face's parameter sliders.
#include "core/mesh/Mesh.h"
#include "ui/panels/PanelContext.h"

#include <memory>
#include <string>

namespace vl::ui {

class RefinementPanel : public SidePanel {
  public:
    explicit RefinementPanel(const PanelContext& context) : session_(context.session) {}
    void draw() override;
    void addProbe(nlohmann::json& summary) const override;

    // What the "Current mesh" section says of the face's (u,v) mesh: refined (by a run now, or saved
    // with the project it was opened from) or the regular base mesh until a refinement.
    static bool isRefinedDomain(const MeshData& domain); // not a regular base mesh
    static std::string meshNote(const MeshData& domain, bool refined, bool ranSinceOpened);

  private:
    bool domainRefined(); // the face's mesh is not the regular base mesh (cached per mesh)

    EditorSession& session_;
    std::shared_ptr<const MeshData> checkedDomain_;
    bool checkedRefined_ = false;
    std::string shownNote_; // the note drawn last frame, for the probe
};

} // namespace vl::ui
