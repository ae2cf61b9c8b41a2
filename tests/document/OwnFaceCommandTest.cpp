// edit::useOwnFace: a face built from a user's mesh and confirmed landmarks replaces the document's
// face as one command (refused with the missing landmarks named), and survives the project file.
// The mesh is a smooth face-sized surface made here, with the landmarks at their canonical (u,v).
#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/document/Document.h"
#include "core/face/FaceFrame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace vl {
namespace {

// A smooth face-shaped surface over (u,v) in [-0.5, 1.5]^2, kSize units across the unit square: its
// eyes lie about 0.29 * kSize apart, about 3.4 times the bundled face's.
constexpr double kSize = 75.0;

OwnFaceCandidate analyticCandidate() {
    MeshData grid;
    const int cells = 80;
    for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
            const Vec2 uv(-0.5 + 2.0 * i / cells, -0.5 + 2.0 * j / cells);
            const double x = kSize * (uv[0] - 0.5), y = kSize * (uv[1] - 0.5);
            grid.uvs.push_back(uv);
            grid.positions.push_back(
                Vec3(x, y, kSize * (0.2 * std::cos(2.4 * x / kSize) + 0.033 * std::sin(3.0 * y / kSize))));
        }
    for (std::uint32_t j = 0; j < cells; ++j)
        for (std::uint32_t i = 0; i < cells; ++i) {
            const std::uint32_t a = j * (cells + 1) + i, b = a + 1, c = a + cells + 2, d = a + cells + 1;
            grid.triangles.push_back({a, b, c});
            grid.triangles.push_back({a, c, d});
        }
    OwnFaceCandidate candidate;
    candidate.file = "big_face.obj";
    candidate.name = "big_face";
    candidate.mesh = std::make_shared<const face::UvMesh>(face::makeUvMesh(grid, "big_face.obj"));
    for (const auto l : face::allLandmarks())
        candidate = placeLandmark(candidate, l, face::canonicalPosition(l));
    return candidate;
}

Document bundledDocument() {
    Document document;
    document.face = makeFaceModel(face::Individual::Bundled, 12);
    document.refinement.kind = CriterionKind::Contour;
    return document;
}

TEST(OwnFaceCommand, RefusesMissingLandmarksByName) {
    OwnFaceCandidate candidate = analyticCandidate();
    candidate.suggestion.landmarks[face::Landmark::NoseTip] = {};
    candidate.suggestion.landmarks[face::Landmark::EyeOuterLeft] = {};
    try {
        (void)edit::useOwnFace(bundledDocument(), candidate);
        FAIL() << "a face without its nose tip was built";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("big_face.obj"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("eye_outer_left, nose_tip"), std::string::npos) << e.what();
    }
    EXPECT_THROW((void)placeLandmark(candidate, face::Landmark::NoseTip, Vec2(7.0, 7.0)), InputError);
}

TEST(OwnFaceCommand, ReplacesTheFaceAndScalesTheCriterion) {
    const Document before = bundledDocument();
    face::FaceBuildReport report;
    const Document after = edit::useOwnFace(before, analyticCandidate(), &report);
    ASSERT_NE(after.face.cascade, nullptr);
    EXPECT_EQ(after.face.cascade->name, "big_face");
    EXPECT_EQ(after.face.parameters, after.face.cascade->defaults());
    EXPECT_EQ(after.face.domain, before.face.domain); // the display mesh is kept
    // Same parameters as the bundled face: presets and viseme vectors apply unchanged.
    ASSERT_EQ(after.face.cascade->parameters.size(), before.face.cascade->parameters.size());
    for (std::size_t k = 0; k < before.face.cascade->parameters.size(); ++k)
        EXPECT_EQ(after.face.cascade->parameters[k].name, before.face.cascade->parameters[k].name);
    EXPECT_GT(report.scale, 2.5);
    EXPECT_NEAR(report.scale, face::faceFrameOf(*after.face.cascade).scaleTo(face::bundledFaceFrame()),
                0.01 * report.scale);
    EXPECT_NEAR(after.refinement.contour.averageError, before.refinement.contour.averageError * report.scale,
                1e-12);
    EXPECT_NEAR(after.refinement.contour.maximumError, before.refinement.contour.maximumError * report.scale,
                1e-12);
    // The jaw opens by a distance that grows with the face.
    const auto aa = oculusVisemes()[10];
    ASSERT_EQ(aa.name, "aa");
    const auto move = [](const DeformationCascade& c, const std::vector<double>& q) {
        return (c.evaluate(0.5, 0.25, q) - c.evaluate(0.5, 0.25, c.defaults())).norm();
    };
    const double own = move(*after.face.cascade, parameterVector(*after.face.cascade, aa));
    const double bundled = move(*before.face.cascade, parameterVector(*before.face.cascade, aa));
    EXPECT_NEAR(own / bundled, report.scale, 0.35 * report.scale);
}

TEST(OwnFaceCommand, OwnFaceSurvivesTheProjectFile) {
    const Document document =
        edit::generateVisemesFromFace(edit::useOwnFace(bundledDocument(), analyticCandidate()));
    const auto dir = std::filesystem::temp_directory_path() / "visemelab-document-ownface";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    saveProject(dir / "p.vlproj", projectFromDocument(document));
    const Document back = documentFromProject(loadProject(dir / "p.vlproj")).document;
    ASSERT_NE(back.face.cascade, nullptr);
    EXPECT_EQ(*back.face.cascade, *document.face.cascade);
    EXPECT_EQ(back.refinement, document.refinement);
    EXPECT_EQ(back.visemes->neutral.positions, document.visemes->neutral.positions);
    std::filesystem::remove_all(dir);
}

} // namespace
} // namespace vl
