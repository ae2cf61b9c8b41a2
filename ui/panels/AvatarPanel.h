#pragma once
// Avatars in the editor's panels: File > Import avatar... and Export avatar..., the Visemes panel's
// avatar section (the meshes, the target pattern that selects the visemes) and the Export panel's
// avatar options. The views draw the avatar's other meshes greyed (EditorUi).
#include "ui/panels/PanelContext.h"

#include <filesystem>
#include <memory>
#include <string>

namespace vl {
struct AvatarScan;
}

namespace vl::ui {

class AvatarPanel {
  public:
    explicit AvatarPanel(const PanelContext& context) : session_(context.session), files_(context.files) {}

    void openImport();
    void openExport();
    void visemesSection(); // Visemes panel: file, target pattern, meshes and their targets
    void exportSection();  // Export panel
    void addProbe(nlohmann::json& summary) const;

  private:
    void gltfpackOption();
    bool gltfpackChosen() const;
    std::string meshReport() const; // of the selected mesh (empty: none selected)

    EditorSession& session_;
    FileActions& files_;
    std::string pattern_;                           // the target pattern being typed
    std::shared_ptr<const AvatarScan> patternScan_; // the scan pattern_ was last reset from
    int meshRow_ = -1;                              // the mesh whose import report is shown
    int names_ = 0;                                 // export: 0 original names, 1 merged
    bool targetNormals_ = true;                     // export: NORMAL/TANGENT displacements of the keys
    int gltfpack_ = -1;                             // export: re-compress (1), not (0), -1: as the input was
    std::filesystem::path gltfpackPath_;            // found once (core/gltf/Gltfpack.h); empty: none
    bool gltfpackSearched_ = false;
};

} // namespace vl::ui
