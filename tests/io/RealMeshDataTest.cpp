// The readers on real face data from ../shared/data (skipped when that folder is absent): the ICT
// FaceKit mouth shapes (quads, per-corner texture coordinates) and MediaPipe's canonical face.
#include "MeshIOTestUtil.h"
#include "core/io/MeshIO.h"

namespace vl {
namespace {

namespace fs = std::filesystem;

const fs::path kShared = VISEMELAB_SHARED_DATA_DIR;

#define SKIP_WITHOUT(folder)                                                                                 \
    if (!fs::is_directory(kShared / (folder)))                                                               \
    GTEST_SKIP() << "shared data folder absent: " << (kShared / (folder))

TEST(RealMeshData, IctMouthShapesShareVertexCountAndTriangles) {
    SKIP_WITHOUT("ict-facekit-mouth");
    const MeshData neutral = readMesh(kShared / "ict-facekit-mouth/generic_neutral_mesh.obj");
    EXPECT_EQ(neutral.vertexCount(), 26719u);
    EXPECT_EQ(neutral.triangles.size(), 52220u); // 25,836 quads + 548 triangles
    ASSERT_EQ(neutral.uvs.size(), neutral.vertexCount());
    std::size_t shapes = 0;
    for (const auto& entry : fs::directory_iterator(kShared / "ict-facekit-mouth")) {
        if (entry.path().extension() != ".obj") continue;
        SCOPED_TRACE(entry.path().string());
        const MeshData shape = readMesh(entry.path());
        EXPECT_EQ(shape.vertexCount(), 26719u);
        EXPECT_EQ(shape.triangles, neutral.triangles);
        EXPECT_EQ(shape.uvs, neutral.uvs); // the files share their vt and f lines
        ++shapes;
    }
    EXPECT_EQ(shapes, 8u);
}

TEST(RealMeshData, IctNeutralRoundTripsThroughEveryFormat) {
    SKIP_WITHOUT("ict-facekit-mouth");
    const MeshData neutral = readMesh(kShared / "ict-facekit-mouth/generic_neutral_mesh.obj");
    test::expectIdenticalMesh(neutral, parseObj(formatObj(neutral), "ict.obj"));
    test::expectIdenticalMesh(neutral, parsePly(formatPly(neutral), "ict.ply"));
    test::expectIdenticalMesh(neutral, parseVrml(formatVrml(neutral), "ict.wrl"));
}

TEST(RealMeshData, MediaPipeCanonicalFaceHasItsDocumentedSize) {
    SKIP_WITHOUT("mediapipe-canonical-face");
    const MeshData face = readMesh(kShared / "mediapipe-canonical-face/canonical_face_model.obj");
    EXPECT_EQ(face.vertexCount(), 468u);
    EXPECT_EQ(face.triangles.size(), 898u);
    ASSERT_EQ(face.uvs.size(), 468u);
    for (const auto& uv : face.uvs) {
        EXPECT_GE(uv[0], 0.0);
        EXPECT_LE(uv[0], 1.0);
        EXPECT_GE(uv[1], 0.0);
        EXPECT_LE(uv[1], 1.0);
    }
    // The fitted portrait has the same topology; the iris variant adds 10 iris vertices.
    EXPECT_EQ(readMesh(kShared / "mediapipe-canonical-face/portrait_face_geometry.obj").triangles,
              face.triangles);
    EXPECT_EQ(readMesh(kShared / "mediapipe-canonical-face/face_model_with_iris.obj").vertexCount(), 478u);
}

} // namespace
} // namespace vl
