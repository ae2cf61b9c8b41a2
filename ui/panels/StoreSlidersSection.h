#pragma once
// Deformation panel, under the sliders: the sliders stored as a new viseme or into an existing one,
// and the face's presets (apply, remove).
#include "ui/panels/PanelContext.h"

#include <string>

namespace vl::ui {

class StoreSlidersSection {
  public:
    explicit StoreSlidersSection(const PanelContext& context) : session_(context.session) {}
    void draw();

  private:
    EditorSession& session_;
    std::string newViseme_; // name of a new viseme from the sliders
    std::string storeInto_; // the existing preset or viseme to store into
};

} // namespace vl::ui
