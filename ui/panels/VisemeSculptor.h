#pragma once
// Shaping the selected viseme on the main view (Visemes panel): grab, smooth, inflate and deflate
// brushes (core/paint/SculptBrush.h) with the weight brush's radius, falloff, X-mirror and front
// faces only; each stroke is one undoable edit. And "Blend...": a new viseme mixed from others.
// View state only: the edits are the session's.
#include "core/paint/BrushRadius.h"
#include "core/paint/PaintSurface.h"
#include "core/paint/SculptBrush.h"
#include "ui/render/Viewport.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

class EditorSession;

struct SculptSettings {
    bool enabled = false; // left drags on the view sculpt the selected viseme (Alt+drag orbits)
    SculptTool tool = SculptTool::Grab;
    BrushRadius radius{8.0, RadiusUnit::PercentOfHead};
    float strength = 0.5f;
    int falloff = 1; // index into the core's falloff kinds
    bool symmetric = true;
    bool frontFacesOnly = true;
};

class VisemeSculptor {
  public:
    VisemeSculptor(EditorSession& session, const Viewport& view) : session_(session), view_(view) {}

    void controls(); // under the viseme list
    // Once per frame over the main view while the Visemes panel shows.
    void sculpt(const ViewportEvents& events);
    // Sculpting is on and a viseme (not the neutral) is selected: left drags are the brush's.
    bool active() const;
    // What the sculpt tests check: the settings, the stroke, the last dab's radius in model units.
    nlohmann::json probe() const;

    SculptSettings settings;

  private:
    SculptDab dab(const Vec3& eye) const; // the dab of the settings, front faces seen from `eye`
    void blendPopup();

    EditorSession& session_;
    const Viewport& view_;
    bool strokeActive_ = false;
    int strokeViseme_ = -1;
    std::vector<Vec3> strokeStart_, strokeShape_;
    PaintSurface strokeSurface_; // the shape under the brush (grab: as the stroke started)
    Vec3 grabPoint_{0, 0, 0};    // grab: the surface point the stroke took hold of
    std::optional<Vec3> lastDab_;
    double strokeRadius_ = 0.0; // model units, fixed for the stroke
    double mirrorX_ = 0.0;      // the neutral's symmetry plane
    int strokeDabs_ = 0;
    double modelRadius_ = 0.0;   // at the cursor, last frame
    double unitsPerPixel_ = 0.0; // likewise
    bool openBlend_ = false;
    std::vector<float> blendWeights_;
    std::string blendName_;
};

} // namespace vl::ui
