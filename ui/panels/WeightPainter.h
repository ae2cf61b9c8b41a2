#pragma once
// The Weights panel's tools on the main view: the brush (radius in screen pixels or % of the head,
// front faces only), the region fill and the box selection, on the viseme set's neutral. Each stroke
// or fill is one undoable edit of the painted weights; the rest is view state.
#include "core/paint/BrushRadius.h"
#include "core/paint/PaintSurface.h"
#include "core/paint/RayPick.h"
#include "ui/render/Viewport.h"
#include "ui/session/EditorSession.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace vl::ui {

struct BrushSettings {
    BrushRadius radius;    // screen pixels or % of the head size
    float strength = 0.5f; // per dab
    int falloff = 1;       // index into the core's falloff kinds
    int mode = 0;          // 0 add, 1 subtract, 2 smooth
    bool symmetric = true;
    bool frontFacesOnly = true; // no paint through to the back of the head (WeightBrush::eye)
    bool enabled = false;
};

// What a left drag on the mesh does while painting is on.
enum class PaintTool { Brush, FillRegion, SelectBox };

struct PaintToolState {
    PaintTool tool = PaintTool::Brush;
    float fillValue = 1.0f;
    float fillTolerance = 0.05f;          // region fill: largest difference to the seed's weight
    std::vector<std::uint32_t> selection; // selected vertices, increasing
    std::optional<ImVec2> boxStart;       // screen corner of the box being dragged
    std::optional<double> readout;        // weight under the cursor (last frame)
    std::uint32_t readoutVertex = 0;      // the vertex nearest to the cursor's hit
    double modelRadius = 0.0;             // the brush radius at the cursor, model units
    double unitsPerPixel = 0.0;           // model units per screen pixel at the cursor
    std::optional<Vec3> boxEye;           // the camera position of the last box selection
};

class WeightPainter {
  public:
    // `view`: the view painted in (its camera aims the brush and the box).
    WeightPainter(EditorSession& session, const Viewport& view) : session_(session), view_(view) {}

    // Once per frame over the view (Weights panel): the readout always, the tools while painting.
    void paint(const ViewportEvents& events);
    // Sets `vertices` to the fill value (one undo step named `action`).
    void fill(const std::vector<std::uint32_t>& vertices, const char* action);
    // Of the viseme set's neutral, rebuilt when the set changes (which clears the selection).
    const PaintSurface& surface();
    // Grows or shrinks the brush by a step, within the radius slider's range ([ and ]).
    void resizeBrush(bool grow);
    // The weights of the stroke being painted (null: none), shown instead of the document's.
    const std::vector<double>* strokeWeights() const { return strokeActive_ ? &strokeWeights_ : nullptr; }
    // The metric's weights as the colours show them, for the readout.
    void setShownWeights(std::vector<double> weights) { shownWeights_ = std::move(weights); }
    // What the paint tests check: the tool, the brush, the selection, the painted means.
    nlohmann::json probe() const;

    BrushSettings brush;
    PaintToolState tools;

  private:
    std::vector<double> startWeights() const;
    void brushStroke(const ViewportEvents& events, const std::optional<RayHit>& hit);
    void boxSelection(const ViewportEvents& events);
    void drawSelection(const ViewportEvents& events);
    std::size_t selectedHidden() const;

    EditorSession& session_;
    const Viewport& view_;
    bool strokeActive_ = false;
    std::vector<double> strokeStart_;
    std::vector<double> strokeWeights_;
    std::optional<Vec3> lastDab_;
    std::vector<double> shownWeights_;
    std::shared_ptr<const VisemeSet> surfaceSet_;
    PaintSurface surface_;
    // How many selected vertices the eye of the last box does not see, found by ray picking
    // (recomputed when the selection changes).
    struct HiddenCount {
        std::vector<std::uint32_t> selection;
        Vec3 eye;
        std::size_t hidden = 0;
    };
    mutable std::optional<HiddenCount> selectionHidden_;
};

} // namespace vl::ui
