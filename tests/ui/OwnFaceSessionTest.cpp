// Issue 32, own face to the end, at the session level: the own-face step's landmarks are document
// state (numeric fields and 3D dots read the same ones); dragging a landmark's dot over the mesh moves
// it snapped to the surface and its release is ONE undo step; a face set's viseme view poses the head's
// parts per viseme; a reopened refined project shows (and says it shows) the refined mesh.
#include "ui/panels/RefinementPanel.h"
#include "ui/session/EditorSession.h"
#include "ui/session/LandmarkDrag.h"

#include "core/common/Error.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl::ui {
namespace {

const std::filesystem::path kSampleNeutral =
    std::filesystem::path(VISEMELAB_ASSETS_DIR) / "sample" / "neutral.obj";

std::filesystem::path ownFaceTempDir(const char* name) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("visemelab-ownface-session-" + std::string(name));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// The ray from far in front of `point` straight at it (the mesh's +z faces the viewer).
std::pair<Vec3, Vec3> rayAt(const Vec3& point) {
    return {point + Vec3(0, 0, 100), Vec3(0, 0, -1)};
}

TEST(OwnFaceSession, DraggingALandmarkSnapsToTheSurfaceAndIsOneUndoStep) {
    EditorSession session;
    session.face().load();
    session.face().openOwnFace(kSampleNeutral);
    ASSERT_NE(session.document().ownFace, nullptr);
    EXPECT_EQ(session.history().undoName(), "Open neutral for its landmarks");
    const OwnFaceCandidate& step = *session.document().ownFace;
    const face::UvMesh& mesh = *step.mesh;
    const face::FoundLandmark before = step.landmarks()[face::Landmark::NoseTip];
    ASSERT_TRUE(before.found());

    // Drag the nose tip through three points of the mesh (vertices of three triangles' centroids):
    // the document does not change until the release.
    LandmarkDrag drag(session);
    drag.begin(face::Landmark::NoseTip);
    const std::uint64_t id = session.history().revision();
    Vec3 target(0, 0, 0);
    for (const std::size_t t :
         {mesh.triangles.size() / 3, mesh.triangles.size() / 2, mesh.triangles.size() / 2 + 7}) {
        const auto& tri = mesh.triangles[t];
        target = (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3.0;
        const auto [origin, direction] = rayAt(target);
        drag.move(origin, direction);
        ASSERT_TRUE(drag.point().has_value());
        EXPECT_EQ(session.history().revision(), id);
    }
    const SurfacePoint shown = *drag.point();
    // A ray that misses the mesh leaves the dot where it was.
    EXPECT_FALSE(drag.move(Vec3(1e6, 1e6, 100), Vec3(0, 0, -1)));
    EXPECT_EQ(drag.point()->uv, shown.uv);
    ASSERT_TRUE(drag.end());

    // One undo step; the landmark is the user's, at the (u,v) under the dot, and lies on the surface
    // where the ray met it (the first hit along the last ray: in front of or at the target point).
    EXPECT_EQ(session.history().undoName(), "Move landmark nose_tip");
    const face::FoundLandmark& moved = session.document().ownFace->landmarks()[face::Landmark::NoseTip];
    EXPECT_EQ(moved.source, face::LandmarkSource::File);
    EXPECT_NEAR(moved.uv[0], shown.uv[0], 1e-12);
    EXPECT_NEAR(moved.uv[1], shown.uv[1], 1e-12);
    EXPECT_LT((moved.position - shown.position).norm(), 1e-6);
    EXPECT_LT(std::hypot(moved.position[0] - target[0], moved.position[1] - target[1]), 1e-6); // on the ray
    EXPECT_GE(moved.position[2], target[2] - 1e-6);
    const face::UvHit closest = face::closestSurfacePoint(mesh, moved.position);
    EXPECT_LT((closest.position - moved.position).norm(), 1e-6);
    EXPECT_GT((moved.position - before.position).norm(), 1e-3);

    session.history().undo();
    EXPECT_EQ(session.history().undoName(), "Open neutral for its landmarks");
    const face::FoundLandmark& restored = session.document().ownFace->landmarks()[face::Landmark::NoseTip];
    EXPECT_EQ(restored.uv, before.uv);
    EXPECT_EQ(restored.source, before.source);
    session.history().redo();
    EXPECT_EQ(session.document().ownFace->landmarks()[face::Landmark::NoseTip].uv, moved.uv);
}

TEST(OwnFaceSession, ANumericDragIsOneStepAndTheBuildClosesTheStep) {
    EditorSession session;
    session.face().load();
    const std::string bundled = session.document().face.cascade->name;
    session.face().openOwnFace(kSampleNeutral);
    const Vec2 start = session.document().ownFace->landmarks()[face::Landmark::MouthCornerLeft].uv;
    // A drag of the u field: several ticks, then the release.
    for (int k = 1; k <= 4; ++k)
        session.face().placeOwnFaceLandmark(face::Landmark::MouthCornerLeft, start + Vec2(0.0005 * k, 0));
    session.history().endEdit();
    EXPECT_EQ(session.history().undoName(), "Move landmark mouth_corner_left");
    session.history().undo();
    EXPECT_EQ(session.document().ownFace->landmarks()[face::Landmark::MouthCornerLeft].uv, start);
    session.history().redo();

    // A (u,v) on no triangle is refused and changes nothing.
    const std::uint64_t id = session.history().revision();
    EXPECT_THROW(session.face().placeOwnFaceLandmark(face::Landmark::NoseTip, Vec2(50, 50)), InputError);
    EXPECT_EQ(session.history().revision(), id);

    // The sample's landmarks the finder could not see, placed by hand: the sample's skin lies on the
    // face domain's (u,v), so each at its canonical place.
    for (const face::Landmark l : face::allLandmarks())
        if (!session.document().ownFace->landmarks()[l].found()) {
            session.face().placeOwnFaceLandmark(l, face::canonicalPosition(l));
            session.history().endEdit();
        }
    EXPECT_EQ(session.document().ownFace->missingRequired(), "");
    session.face().buildOwnFace();
    EXPECT_EQ(session.document().ownFace, nullptr);
    EXPECT_EQ(session.document().face.cascade->name, "neutral");
    session.history().undo(); // back to the step, the face untouched
    ASSERT_NE(session.document().ownFace, nullptr);
    EXPECT_EQ(session.document().face.cascade->name, bundled);
    session.face().cancelOwnFace();
    EXPECT_EQ(session.document().ownFace, nullptr);
    EXPECT_EQ(session.document().face.cascade->name, bundled);
}

TEST(OwnFaceSession, AFaceSetPosesTheHeadPartsPerViseme) {
    EditorSession session;
    session.face().load();
    session.face().generateVisemes();
    ASSERT_TRUE(session.authoring().visemeSetMadeByFace());
    const auto& parameters = session.authoring().visemeFaceParameters();
    ASSERT_EQ(parameters.size(), session.visemeCount());
    // Each viseme's vector is its preset's: "aa" opens the jaw, "PP" does not.
    const auto& cascade = *session.document().face.cascade;
    const int jaw = cascade.findParameter("jaw_open");
    ASSERT_GE(jaw, 0);
    const int aa = session.visemes()->find("aa"), pp = session.visemes()->find("PP");
    ASSERT_GE(aa, 0);
    ASSERT_GE(pp, 0);
    EXPECT_GT(parameters[static_cast<std::size_t>(aa)][static_cast<std::size_t>(jaw)],
              parameters[static_cast<std::size_t>(pp)][static_cast<std::size_t>(jaw)] + 0.2);
    // A set that is not the face's (another face now): no parameters, so no parts.
    session.face().setIndividual(face::Individual::Retarget);
    EXPECT_FALSE(session.authoring().visemeSetMadeByFace());
    EXPECT_TRUE(session.authoring().visemeFaceParameters().empty());
}

TEST(OwnFaceSession, AReopenedRefinedProjectShowsTheRefinedMeshAndSaysSo) {
    const auto dir = ownFaceTempDir("refined");
    EditorSession session;
    session.face().load();
    EXPECT_FALSE(RefinementPanel::isRefinedDomain(*session.document().face.domain));
    EXPECT_NE(
        RefinementPanel::meshNote(*session.document().face.domain, false, false).find("regular base mesh"),
        std::string::npos);
    session.face().startRefinement(RefineAction::Refine);
    session.finishBackgroundWork();
    ASSERT_TRUE(session.face().lastRefinement().has_value());
    const MeshData refined = *session.document().face.domain;
    ASSERT_TRUE(RefinementPanel::isRefinedDomain(refined));
    session.files().saveProject(dir / "refined.vlproj");

    EditorSession reopened;
    reopened.files().openProject(dir / "refined.vlproj");
    ASSERT_NE(reopened.document().face.cascade, nullptr);
    EXPECT_EQ(reopened.document().face.domain->uvs.size(), refined.uvs.size());
    EXPECT_EQ(reopened.document().face.domain->triangles, refined.triangles);
    EXPECT_FALSE(reopened.face().lastRefinement().has_value());
    EXPECT_TRUE(RefinementPanel::isRefinedDomain(*reopened.document().face.domain));
    const std::string note = RefinementPanel::meshNote(*reopened.document().face.domain, true, false);
    EXPECT_NE(note.find("refined mesh saved with the project"), std::string::npos) << note;
    EXPECT_EQ(note.find("regular"), std::string::npos) << note;
}

} // namespace
} // namespace vl::ui
