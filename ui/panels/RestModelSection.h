#pragma once
#include "ui/session/EditorSession.h"

namespace vl::ui {

// The Reduction panel's model: the rest pose free or a key, the rest viseme, adding one. No view
// state: every choice is an undoable edit of the document.
void restModelSection(EditorSession& session);

} // namespace vl::ui
