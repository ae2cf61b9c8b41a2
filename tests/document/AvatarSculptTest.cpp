// Sculpting an avatar's viseme (issue 32 pt 2): only the meshes carrying a target of it move, the
// export maps the world-space shape back into each mesh's own space (scaled armature, skinned head,
// node-placed eyes; every storage) so that reading the output gives the sculpted shape again, the
// visemes not sculpted keep their accessors, and a project keeps the sculpt.
#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/document/AvatarDocument.h"
#include "core/document/Commands.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GltfDocument.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/project/Project.h"
#include "core/project/ProjectRun.h"
#include "core/reduce/ReducedModel.h"
#include "tests/gltf/AvatarFixtures.h"

#include "tests/document/DocumentTestSupport.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace vl {
namespace {

using test::FixtureStorage;

Document rpmDocumentStored(const std::filesystem::path& dir, FixtureStorage storage = FixtureStorage::Plain) {
    std::filesystem::create_directories(dir);
    const auto file = dir / "rpm.glb";
    test::AvatarFixtureOptions options;
    options.storage = storage;
    writeFileAtomically(file, test::rpmLikeAvatar(options));
    return documentFromAvatar(loadDocumentAvatar(file, ""),
                              bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus"));
}

std::size_t indexOf(const Document& document, const std::string& name) {
    const auto names = visemeNames(document);
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

// The viseme's shape pushed out along +y and +z by a smooth bump over its vertices (metres).
std::vector<Vec3> bumped(const Document& document, std::size_t viseme) {
    std::vector<Vec3> shape = document.visemes->visemes[viseme].positions;
    for (std::size_t v = 0; v < shape.size(); ++v) {
        const double s = 0.004 * std::sin(0.37 * static_cast<double>(v));
        shape[v] += Vec3(0.0, s, 0.5 * s + 0.002);
    }
    return shape;
}

double largestDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double d = 0;
    for (std::size_t v = 0; v < a.size(); ++v) d = std::max(d, (a[v] - b[v]).norm());
    return d;
}

std::vector<int> eachAlone(std::size_t n) {
    std::vector<int> groupOf(n);
    std::iota(groupOf.begin(), groupOf.end(), 0);
    return groupOf;
}

TEST(AvatarSculpt, OnlyTheMeshesCarryingTheVisemeMove) {
    const Document document = rpmDocumentStored(test::tempDir("avatar-sculpt-meshes"));
    const std::size_t aa = indexOf(document, "viseme_aa");
    const Document next = edit::setVisemeShape(document, static_cast<int>(aa), bumped(document, aa));
    const std::vector<char> movable = avatarSculptableVertices(*document.avatar.scan, aa);
    const auto& before = document.visemes->visemes[aa].positions;
    const auto& after = next.visemes->visemes[aa].positions;
    std::size_t moved = 0, kept = 0;
    for (std::size_t v = 0; v < before.size(); ++v) {
        if (movable[v]) {
            EXPECT_GT((after[v] - before[v]).norm(), 1e-3) << v;
            ++moved;
        } else {
            EXPECT_EQ(after[v], before[v]) << v;
            ++kept;
        }
    }
    EXPECT_GT(moved, 0u);
    // The other visemes and the file's own set are untouched; the document reports one sculpt.
    for (std::size_t i = 0; i < document.visemeCount(); ++i) {
        if (i == aa) continue;
        EXPECT_EQ(next.visemes->visemes[i].positions, document.visemes->visemes[i].positions);
    }
    EXPECT_EQ(document.avatar.scan->set.visemes[aa].positions, before);
    const auto sculpted = sculptedAvatarVisemes(next);
    ASSERT_EQ(sculpted.size(), document.visemeCount());
    for (std::size_t i = 0; i < sculpted.size(); ++i) EXPECT_EQ(sculpted[i].empty(), i != aa) << i;
    EXPECT_TRUE(sculptedAvatarVisemes(document).empty());
}

// Every storage the writer keeps (plain, quantised, meshopt, sparse): the output, read back, holds
// the sculpted shape in world space; the visemes not sculpted come back exactly.
TEST(AvatarSculpt, ExportWritesTheSculptedShapeInEachMeshsOwnSpace) {
    for (const FixtureStorage storage : {FixtureStorage::Plain, FixtureStorage::Quantised,
                                         FixtureStorage::Meshopt, FixtureStorage::Sparse}) {
        SCOPED_TRACE(static_cast<int>(storage));
        const Document document = rpmDocumentStored(
            test::tempDir("avatar-sculpt-export-" + std::to_string(static_cast<int>(storage))), storage);
        const std::size_t aa = indexOf(document, "viseme_aa");
        const std::vector<Vec3> shape = bumped(document, aa);
        const Document next = edit::setVisemeShape(document, static_cast<int>(aa), shape);
        const std::string glb = reducedAvatarGlb(next, eachAlone(next.visemeCount()));
        const AvatarScan out = scanAvatar(parseGltfDocument(glb, "out.glb", {}), {""});
        ASSERT_EQ(out.visemes, document.avatar.scan->visemes);
        // A sculpted target is written as floats (compressed if its member was), whatever the grid.
        const double tolerance = 1e-6;
        EXPECT_LT(largestDistance(out.set.visemes[aa].positions, next.visemes->visemes[aa].positions),
                  tolerance);
        EXPECT_GT(largestDistance(out.set.visemes[aa].positions, document.visemes->visemes[aa].positions),
                  1e-3);
        for (std::size_t i = 0; i < out.set.size(); ++i) {
            if (i == aa) continue;
            EXPECT_EQ(out.set.visemes[i].positions, document.avatar.scan->set.visemes[i].positions)
                << out.visemes[i];
        }
    }
}

// A key with a sculpted member is the frequency-weighted mean of the sculpted shape and the others
// (the reduced model the editor computes), in the output as in the document.
TEST(AvatarSculpt, AMergedKeyMixesTheSculptedShape) {
    const Document document = rpmDocumentStored(test::tempDir("avatar-sculpt-merged"));
    const std::size_t aa = indexOf(document, "viseme_aa"), e = indexOf(document, "viseme_E");
    const Document next = edit::setVisemeShape(document, static_cast<int>(aa), bumped(document, aa));
    std::vector<int> groupOf = eachAlone(next.visemeCount());
    groupOf[e] = groupOf[aa]; // aa and E share a key; renumbered below so the keys are 0..m-1
    std::vector<int> compact(groupOf.size());
    std::vector<int> seen;
    for (std::size_t i = 0; i < groupOf.size(); ++i) {
        auto it = std::find(seen.begin(), seen.end(), groupOf[i]);
        if (it == seen.end()) {
            seen.push_back(groupOf[i]);
            it = seen.end() - 1;
        }
        compact[i] = static_cast<int>(it - seen.begin());
    }
    const std::vector<double> frequencies = documentFrequencies(next);
    const ReducedModel model = buildReducedModel(*next.visemes, frequencies, compact, next.frequencies);
    const std::string glb = reducedAvatarGlb(next, compact);
    const AvatarScan out = scanAvatar(parseGltfDocument(glb, "out.glb", {}), {""});
    const auto& key = model.keys[static_cast<std::size_t>(compact[aa])].positions;
    EXPECT_LT(largestDistance(out.set.visemes[aa].positions, key), 1e-6);
    EXPECT_LT(largestDistance(out.set.visemes[e].positions, key), 1e-6);
}

TEST(AvatarSculpt, AProjectKeepsTheSculptAndRefusesAShapeOfAnotherSize) {
    const auto dir = test::tempDir("avatar-sculpt-project");
    const Document document = rpmDocumentStored(dir);
    const std::size_t aa = indexOf(document, "viseme_aa");
    const Document next = edit::setVisemeShape(document, static_cast<int>(aa), bumped(document, aa));
    Project project = projectFromDocument(next);
    project.path = dir / "rpm.visemelab.json";
    saveProject(project.path, project);
    const nlohmann::json saved = nlohmann::json::parse(readFileToString(project.path));
    EXPECT_EQ(saved["version"], 5); // the lowest version that holds a sculpted avatar viseme
    EXPECT_EQ(saved["visemes"][aa]["positions"].size(), next.visemes->vertexCount());
    EXPECT_FALSE(saved["visemes"][0].contains("positions"));
    const Project loaded = loadProject(project.path);
    nlohmann::json older = saved; // a version-4 file cannot hold a sculpt: refused, with its path
    older["version"] = 4;
    writeFileAtomically(dir / "older.visemelab.json", older.dump());
    try {
        loadProject(dir / "older.visemelab.json");
        ADD_FAILURE() << "a version-4 file with a sculpted avatar viseme was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("/positions"), std::string::npos) << error.what();
    }
    ASSERT_EQ(loaded.visemes[aa].positions.size(), next.visemes->vertexCount());
    const Document reopened = documentFromProject(loaded).document;
    EXPECT_EQ(reopened.visemes->visemes[aa].positions, next.visemes->visemes[aa].positions);
    EXPECT_EQ(sculptedAvatarVisemes(reopened).size(), next.visemeCount());
    // The CLI's view of the same project (reduce, say) sees the sculpt too.
    EXPECT_EQ(loadProjectVisemeSet(loaded).visemes[aa].positions, next.visemes->visemes[aa].positions);

    Project broken = loaded;
    broken.visemes[aa].positions.pop_back();
    try {
        documentFromProject(broken);
        ADD_FAILURE() << "a sculpted shape of the wrong size was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("viseme_aa"), std::string::npos) << error.what();
    }
    EXPECT_THROW(loadProjectVisemeSet(broken), InputError);
}

TEST(AvatarSculpt, AddingTheRestVisemeKeepsTheSculpt) {
    const auto dir = test::tempDir("avatar-sculpt-rest");
    std::filesystem::create_directories(dir);
    test::AvatarFixtureOptions options;
    options.restTarget = false;
    writeFileAtomically(dir / "rpm.glb", test::rpmLikeAvatar(options));
    const FrequencySource table = bundledPhonemeFrequencies(VISEMELAB_ASSETS_DIR, "oculus");
    const Document document = documentFromAvatar(loadDocumentAvatar(dir / "rpm.glb", ""), table);
    const std::size_t aa = indexOf(document, "viseme_aa");
    const Document sculpted = edit::setVisemeShape(document, static_cast<int>(aa), bumped(document, aa));
    const Document rested = edit::addAvatarRestViseme(sculpted, table);
    EXPECT_EQ(rested.visemeCount(), document.visemeCount() + 1);
    EXPECT_EQ(rested.visemes->visemes[aa].positions, sculpted.visemes->visemes[aa].positions);
    // The added rest is the base mesh, no target's: nothing to sculpt.
    const int rest = static_cast<int>(rested.visemeCount()) - 1;
    EXPECT_THROW(edit::setVisemeShape(rested, rest, bumped(rested, static_cast<std::size_t>(rest))),
                 InputError);
}

} // namespace
} // namespace vl
