#pragma once
// The Reduction panel's constraints: visemes pinned as their own key, pairs kept apart, pairs kept
// together; each change is one undoable edit of the document.
#include "ui/panels/PanelContext.h"

namespace vl::ui {

class ConstraintsSection {
  public:
    explicit ConstraintsSection(const PanelContext& context) : session_(context.session) {}
    void draw();

  private:
    EditorSession& session_;
    // The visemes chosen in the combos.
    int pin_ = 0, first_ = 0, second_ = 1;
};

} // namespace vl::ui
