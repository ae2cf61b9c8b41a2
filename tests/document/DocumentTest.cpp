// The document and its file form: a project loads into a document and a document saves back to
// the same project; comparisons are exact and defaulted (a new field cannot be forgotten).
#include "core/document/Document.h"
#include "core/adaptive/CascadeSurface.h"
#include "core/document/Commands.h"
#include "core/io/MeshIO.h"

#include "DocumentTestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace vl {
namespace {

using test::faceDocument;
using test::tempDir;

TEST(Document, EmbeddedDocumentSurvivesTheProjectFileExactly) {
    Document document = faceDocument();
    document = edit::setTarget(document, 5);
    document = edit::setVisemeFrequency(document, 2, 3.5);
    document = edit::setWeightMode(document, WeightMode::Area);
    document = edit::setParameter(document, 0, 0.25);
    const auto dir = tempDir("embedded");
    const Project project = projectFromDocument(document, {}, "PP");
    saveProject(dir / "p.vlproj", project);
    const LoadedProject loaded = documentFromProject(loadProject(dir / "p.vlproj"));
    EXPECT_EQ(loaded.selectedViseme, "PP");
    const Document& back = loaded.document;
    ASSERT_NE(back.visemes, nullptr);
    EXPECT_EQ(back.visemes->neutral, document.visemes->neutral);
    for (std::size_t i = 0; i < document.visemeCount(); ++i)
        EXPECT_EQ(back.visemes->visemes[i].positions, document.visemes->visemes[i].positions);
    EXPECT_EQ(back.frequencies, document.frequencies);
    EXPECT_EQ(back.weights.mode, WeightMode::Area);
    EXPECT_EQ(back.target, 5);
    EXPECT_EQ(*back.face.cascade, *document.face.cascade);
    EXPECT_EQ(back.face.parameters, document.face.parameters);
    EXPECT_EQ(back.refinement, document.refinement);
    // Saved again, the project is the same value.
    Project again = projectFromDocument(back, {}, "PP");
    EXPECT_EQ(again, project);
}

// Issue 15: a refined face mesh is part of the project. Refined for every viseme, set as the face's
// mesh and the visemes generated on it, it is saved (version 2) and comes back on open: the face's
// (u,v) mesh and the viseme meshes equal, where before the reopened face fell back to the default grid.
TEST(Document, ARefinedFaceMeshIsSavedAndComesBackOnOpen) {
    Document document;
    document.face = makeFaceModel(face::Individual::Bundled); // the default mesh: not written
    EXPECT_TRUE(projectFromDocument(document).deformation.domain.positions.empty());

    CriterionSettings settings;
    settings.kind = CriterionKind::Contour;
    settings.maxDepth = 4;
    std::vector<std::vector<double>> poses;
    for (const VisemeParameters& viseme : oculusVisemes())
        poses.push_back(parameterVector(*document.face.cascade, viseme));
    const auto refined =
        std::make_shared<const MeshData>(refineFaceMesh(*document.face.cascade, 10, settings, poses));
    document = edit::generateVisemesFromFace(edit::setFaceDomain(document, refined));
    ASSERT_EQ(document.visemes->neutral.uvs, refined->uvs);

    const auto dir = tempDir("refined");
    saveProject(dir / "p.vlproj", projectFromDocument(document));
    EXPECT_EQ(projectVersionFor(loadProject(dir / "p.vlproj")), 3); // a new document: its rest model
    // Keyed, the face's (u,v) mesh alone needs version 2.
    document = edit::setRest(document, RestChoice::Key, "");
    saveProject(dir / "p.vlproj", projectFromDocument(document));
    const Project project = loadProject(dir / "p.vlproj");
    EXPECT_EQ(projectVersionFor(project), 2);
    const Document back = documentFromProject(project).document;
    ASSERT_NE(back.face.domain, nullptr);
    EXPECT_EQ(back.face.domain->uvs, refined->uvs);
    EXPECT_EQ(back.face.domain->triangles, refined->triangles);
    EXPECT_EQ(back.visemes->neutral, document.visemes->neutral);
    EXPECT_EQ(back.visemes->visemes.back().positions, document.visemes->visemes.back().positions);
    // Generating the visemes again on the reopened face gives the same meshes.
    const Document regenerated = edit::generateVisemesFromFace(back);
    EXPECT_EQ(regenerated.visemes->visemes[3].positions, document.visemes->visemes[3].positions);
}

TEST(Document, FileMeshesAreReferencedByAbsolutePathAndReadOnce) {
    const Document generated = faceDocument();
    const auto dir = tempDir("files");
    writeMesh(dir / "neutral.obj", generated.visemes->neutral);
    Project project;
    project.path = dir / "p.vlproj";
    project.neutral.file = "neutral.obj";
    for (std::size_t i = 0; i < 3; ++i) {
        const std::string name = generated.visemes->visemes[i].name;
        writeMesh(dir / (name + ".obj"), generated.visemes->meshOf(i));
        project.visemes.push_back({name, name + ".obj", {}});
        project.frequencies.visemeFrequencies.entries.emplace_back(name, 1.0);
    }
    project.reduction.target = 2;
    saveProject(dir / "p.vlproj", project);
    const Document document = documentFromProject(loadProject(dir / "p.vlproj")).document;
    EXPECT_EQ(document.neutralFile, std::filesystem::absolute(dir / "neutral.obj"));
    ASSERT_EQ(document.visemeFiles.size(), 3u);
    EXPECT_TRUE(document.visemeFiles[1].is_absolute());
    // The saved form points to the same files and embeds nothing.
    const Project back = projectFromDocument(document);
    EXPECT_TRUE(back.neutral.embedded.positions.empty());
    EXPECT_TRUE(back.visemes[0].positions.empty());
    EXPECT_EQ(resolveProjectFile(back, back.visemes[2].file),
              std::filesystem::absolute(dir / project.visemes[2].file));
}

TEST(Document, ComparisonSeesEveryPartAndSharesGeometryByIdentity) {
    const Document a = faceDocument();
    Document b = a;
    EXPECT_EQ(a, b);
    b.refinement.contour.samplesPerSide += 1;
    EXPECT_NE(a, b);
    b = a;
    b.visemes = std::make_shared<const VisemeSet>(*a.visemes); // same values, another mesh object
    EXPECT_NE(a, b);
    EXPECT_FALSE(sameReductionInputs(a, b));
    b = edit::setParameter(a, 1, 0.5);
    EXPECT_TRUE(sameReductionInputs(a, b)); // a slider move does not invalidate the reduction
    // Where a table was read from is not part of its value.
    b = a;
    b.frequencies.origin.text = "elsewhere.json";
    EXPECT_EQ(a, b);
}

} // namespace
} // namespace vl
