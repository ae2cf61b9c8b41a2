#pragma once
// A session header that reaches into the renderer and ImGui: the check must refuse both.
#include "ui/render/Camera.h"

#include <imgui.h>
