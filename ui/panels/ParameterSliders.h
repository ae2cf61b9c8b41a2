#pragma once
#include "ui/session/EditorSession.h"

namespace vl::ui {

// The face's parameters: a viseme preset, the defaults, one live slider per parameter (in the
// Deformation and the Refinement panels: the view shows the face at these values). Needs a face.
void parameterSliders(EditorSession& session);

} // namespace vl::ui
