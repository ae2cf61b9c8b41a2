#pragma once
// Visemes panel, under the list: rename, duplicate, move and delete the selected viseme; a delete
// that would leave phonemes unmapped asks where they go. View state only: the edits are the session's.
#include "ui/panels/PanelContext.h"

#include <cstdint>
#include <string>

namespace vl::ui {

class VisemeAuthoring {
  public:
    explicit VisemeAuthoring(const PanelContext& context) : session_(context.session) {}
    void draw();
    // What the authoring tests check: viseme names, presets, parameters, frequencies, the map.
    void addProbe(nlohmann::json& summary) const;

  private:
    void deletePopup();

    EditorSession& session_;
    int nameFor_ = -2;               // the viseme whose name the rename field holds
    std::uint64_t nameDocument_ = 0; // ... in this document state
    bool editingName_ = false;       // the field had the keyboard last frame
    std::string name_;               // the rename field
    bool openDelete_ = false;        // open the delete popup next frame
    int deleteIndex_ = -1;           // the viseme the popup deletes
    std::string phonemesGoTo_;       // where its phonemes go
};

} // namespace vl::ui
