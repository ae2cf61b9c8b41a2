#pragma once
// What the weight brush and the sculpt brush share on the view: the size of a screen pixel at a
// surface point (it grows with the point's depth) and the brush's circle drawn there.
#include "core/mesh/Mesh.h"
#include "ui/render/Camera.h"
#include "ui/render/Viewport.h"

#include <imgui.h>

namespace vl::ui {

// Model units per screen pixel at `point` in the view of `events` (core/paint/BrushRadius.h).
// Throws InputError for a degenerate view.
double unitsPerPixelAt(const OrbitCamera& camera, const ViewportEvents& events, const Vec3& point);

// A circle of `radius` model units around `point`, in the view's image.
void drawBrushCircle(const OrbitCamera& camera, const ViewportEvents& events, const Vec3& point,
                     double radius, double unitsPerPixel, ImU32 colour);

} // namespace vl::ui
