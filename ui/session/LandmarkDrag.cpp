#include "ui/session/LandmarkDrag.h"

#include "core/paint/RayPick.h"
#include "ui/session/EditorSession.h"

namespace vl::ui {

std::optional<SurfacePoint> pickSurface(const face::UvMesh& mesh, const Vec3& origin, const Vec3& direction) {
    const std::optional<RayHit> hit = intersectRay(mesh.positions, mesh.triangles, origin, direction);
    if (!hit) return std::nullopt;
    // The hit's (u,v): the same barycentric weights over the triangle's texture corners (seams keep
    // the side the ray met).
    const Triangle& tex = mesh.texTriangles[hit->triangle];
    Vec2 uv(0, 0);
    for (int k = 0; k < 3; ++k) uv += mesh.texCoords[tex[k]] * hit->barycentric[k];
    return SurfacePoint{hit->point, uv, hit->distance};
}

void LandmarkDrag::begin(face::Landmark landmark) {
    point_.reset();
    landmark_.reset();
    if (session_.document().ownFace) landmark_ = landmark;
}

bool LandmarkDrag::move(const Vec3& origin, const Vec3& direction) {
    const auto& step = session_.document().ownFace;
    if (!landmark_ || !step) return false;
    const std::optional<SurfacePoint> hit = pickSurface(*step->mesh, origin, direction);
    if (hit) point_ = hit;
    return hit.has_value();
}

bool LandmarkDrag::end() {
    const std::optional<face::Landmark> landmark = landmark_;
    const std::optional<SurfacePoint> point = point_;
    cancel();
    if (!landmark || !point) return true;
    const bool placed = session_.attempt("Move landmark",
                                         [&] { session_.face().placeOwnFaceLandmark(*landmark, point->uv); });
    session_.history().endEdit(); // the next drag is its own undo step
    return placed;
}

} // namespace vl::ui
