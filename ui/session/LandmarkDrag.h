#pragma once
// Dragging a landmark of the own-face step (Document::ownFace) on its mesh in the 3D view: while the
// button is held the landmark's dot follows the cursor snapped to the surface (the first triangle the
// picking ray meets, core/paint/RayPick.h) and the document is untouched; the release places the
// landmark at the (u,v) under the dot as ONE undo step (SessionFace::placeOwnFaceLandmark). No GL
// or ImGui: the view hands in rays, the session tests drive it alike.
#include "core/face/Landmarks.h"
#include "core/face/UvMesh.h"

#include <optional>

namespace vl::ui {

class EditorSession;

// A point of a (u,v) mesh under a ray: where on the surface and at which texture-space point.
struct SurfacePoint {
    Vec3 position{0, 0, 0};
    Vec2 uv{0, 0};
    double distance = 0.0; // along the ray
};
// The first surface point along the ray (either face of a triangle), or none when it misses.
std::optional<SurfacePoint> pickSurface(const face::UvMesh& mesh, const Vec3& origin, const Vec3& direction);

class LandmarkDrag {
  public:
    explicit LandmarkDrag(EditorSession& session) : session_(session) {}

    // Takes hold of `landmark` (of the open own-face step; nothing happens without one).
    void begin(face::Landmark landmark);
    // The ray under the cursor: the dot moves to where it meets the mesh, and stays where it was
    // when the ray misses. Returns whether the dot is on the surface under the cursor.
    bool move(const Vec3& origin, const Vec3& direction);
    // Places the landmark where the dot is (one undo step "Move landmark NAME"), or nothing when it
    // never moved; false when the session refused (its message says why).
    bool end();
    void cancel() { landmark_.reset(), point_.reset(); }

    std::optional<face::Landmark> landmark() const { return landmark_; }
    // Where the dragged dot is shown (none before the first move).
    const std::optional<SurfacePoint>& point() const { return point_; }

  private:
    EditorSession& session_;
    std::optional<face::Landmark> landmark_;
    std::optional<SurfacePoint> point_;
};

} // namespace vl::ui
