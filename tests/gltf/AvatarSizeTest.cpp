// Reduced avatars are smaller than their input, in every storage the fixtures have, and the new
// keys keep the input's precision (core/gltf/TargetStorage.h).
#include "core/gltf/Accessors.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/BufferViews.h"
#include "core/gltf/GltfDocument.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace vl {
namespace {

using test::FixtureStorage;

struct Kind {
    const char* name;
    std::string glb;
    std::string pattern;
};

std::vector<Kind> kinds() {
    std::vector<Kind> out;
    const std::pair<const char*, FixtureStorage> storages[] = {{"rpm_plain", FixtureStorage::Plain},
                                                               {"rpm_quantised", FixtureStorage::Quantised},
                                                               {"rpm_meshopt", FixtureStorage::Meshopt},
                                                               {"rpm_sparse", FixtureStorage::Sparse},
                                                               {"rpm_draco", FixtureStorage::Draco}};
    for (const auto& [name, storage] : storages) {
        test::AvatarFixtureOptions options;
        options.storage = storage;
        out.push_back({name, test::rpmLikeAvatar(options), ""});
    }
    out.push_back({"vroid_vrm0", test::vroidLikeAvatar(false), "Fcl_MTH_[AIUEO]"});
    out.push_back({"vroid_vrm1", test::vroidLikeAvatar(true), "Fcl_MTH_[AIUEO]"});
    return out;
}

AvatarReduction reduced(const GltfDocument& doc, const AvatarScan& scan, int m, AvatarNames names) {
    ReduceSettings settings;
    settings.target = m;
    AvatarWriteOptions write;
    write.names = names;
    return reduceAvatar(doc, scan, uniformFrequencies(scan), settings, write);
}

// Bytes of the key table VisemeLab adds to the JSON: the root's extras.visemelab and each mesh's
// extras.visemeKeys and extras.targetAliases (compact, as written; core/gltf/KeyTable.h).
std::size_t keyTableBytes(const std::string& glb) {
    const GltfDocument doc = parseGltfDocument(glb, "out.glb", {});
    std::size_t bytes = doc.json["extras"]["visemelab"].dump().size();
    for (const auto& mesh : doc.json["meshes"])
        if (mesh.contains("extras"))
            for (const char* key : {"visemeKeys", "targetAliases"})
                if (mesh["extras"].contains(key)) bytes += mesh["extras"][key].dump().size();
    return bytes;
}

// Smaller for every m < n, in every storage and both names modes. At m = n - 1 the rpm fixtures merge
// one pair of visemes, which saves one target's data per mesh (about 6 KB on the compressed kinds);
// the key table (core/gltf/KeyTable.h: once at the root, per mesh only its key targets) adds less.
TEST(AvatarSize, EveryReductionIsSmallerThanItsInputInEveryStorageAndNamesMode) {
    for (const Kind& kind : kinds()) {
        const GltfDocument doc = parseGltfDocument(kind.glb, "in.glb", {});
        const AvatarScan scan = scanAvatar(doc, {kind.pattern});
        const int n = static_cast<int>(scan.visemes.size());
        ASSERT_GE(n, 5) << kind.name;
        for (int m = 1; m < n; ++m)
            for (AvatarNames names : {AvatarNames::Original, AvatarNames::Merged}) {
                const AvatarReduction r = reduced(doc, scan, m, names);
                const std::size_t table = keyTableBytes(r.glb);
                const std::string what = std::string(kind.name) + " m=" + std::to_string(m) + " names " +
                                         toString(names) + ": " + std::to_string(r.glb.size()) +
                                         " bytes out (key table " + std::to_string(table) + "), " +
                                         std::to_string(kind.glb.size()) + " in";
                EXPECT_LT(r.glb.size(), kind.glb.size()) << what;
                if (m == n - 1) std::printf("%s\n", what.c_str());
            }
    }
}

// Every key accessor with bytes is stored as the input's targets are: shorts in, shorts out;
// compressed in, compressed out (or sparse, when that is smaller).
TEST(AvatarSize, KeysFollowTheInputStorageAndTheNotesSaySo) {
    for (FixtureStorage storage : {FixtureStorage::Quantised, FixtureStorage::Meshopt}) {
        test::AvatarFixtureOptions options;
        options.storage = storage;
        const GltfDocument doc = parseGltfDocument(test::rpmLikeAvatar(options), "in.glb", {});
        const AvatarScan scan = scanAvatar(doc, {""});
        const AvatarReduction r = reduced(doc, scan, 4, AvatarNames::Merged);
        const GltfDocument out = parseGltfDocument(r.glb, "out.glb", {});
        std::size_t compressed = 0, shorts = 0;
        for (const auto& mesh : out.model.meshes)
            for (const auto& prim : mesh.primitives)
                for (const auto& target : prim.targets)
                    for (const auto& [name, index] : target) {
                        const auto& a = out.model.accessors[static_cast<std::size_t>(index)];
                        if (a.bufferView < 0 && !a.sparse.isSparse) continue; // all zero
                        if (storage == FixtureStorage::Quantised) {
                            EXPECT_EQ(a.componentType, 5122) << mesh.name << " " << name;
                            EXPECT_TRUE(a.normalized);
                            shorts += a.componentType == 5122;
                        } else {
                            EXPECT_EQ(a.componentType, 5126);
                            const auto& view = out.json["bufferViews"][static_cast<std::size_t>(
                                a.bufferView >= 0 ? a.bufferView : a.sparse.values.bufferView)];
                            compressed += view.contains("extensions");
                        }
                    }
        std::string notes;
        for (const auto& note : r.summary.notes) notes += note + "\n";
        if (storage == FixtureStorage::Quantised) {
            EXPECT_GT(shorts, 0u);
            EXPECT_NE(notes.find("SHORT normalised"), std::string::npos) << notes;
        } else {
            EXPECT_GT(compressed, 0u);
            EXPECT_NE(notes.find("EXT_meshopt_compression EXPONENTIAL 15 bits"), std::string::npos) << notes;
        }
        EXPECT_EQ(notes.find("uncompressed"), std::string::npos) << notes;
    }
}

// Written from a Meshopt or Sparse fixture (the Plain fixture's geometry, stored differently), the
// keys read back through the scan equal those written from the Plain fixture, within the input's
// quantisation step: the exponential filter's (below), exact for sparse floats.
TEST(AvatarSize, KeysReadBackWithinTheInputStepOfTheFloatReference) {
    const auto scanned = [](FixtureStorage storage, int m) {
        test::AvatarFixtureOptions options;
        options.storage = storage;
        const GltfDocument doc = parseGltfDocument(test::rpmLikeAvatar(options), "in.glb", {});
        const AvatarReduction r = reduced(doc, scanAvatar(doc, {""}), m, AvatarNames::Merged);
        const GltfDocument out = parseGltfDocument(r.glb, "out.glb", {});
        return std::make_pair(r.outcome.result.groupOf(), scanAvatar(out, {""}));
    };
    for (int m : {3, 7, 12}) {
        const auto [plainGroups, plain] = scanned(FixtureStorage::Plain, m);
        for (FixtureStorage storage : {FixtureStorage::Meshopt, FixtureStorage::Sparse}) {
            const auto [groups, got] = scanned(storage, m);
            ASSERT_EQ(groups, plainGroups) << "m=" << m << ": the same grouping is needed to compare";
            ASSERT_EQ(got.visemes, plain.visemes);
            ASSERT_EQ(got.set.size(), plain.set.size());
            ASSERT_EQ(got.set.vertexCount(), plain.set.vertexCount());
            // meshoptimizer 0.18's exponential filter takes a zero component's exponent as 0 (frexp),
            // so for deltas below 1 with 15 bits the step is at most 2^-14: half of it lost on the
            // members, half on the key.
            const double step = storage == FixtureStorage::Meshopt ? std::ldexp(1.0, -14) : 0.0;
            for (std::size_t i = 0; i < plain.set.size(); ++i)
                for (std::size_t v = 0; v < plain.set.vertexCount(); ++v) {
                    // World space: the per-component bound becomes one on the vector's length, times
                    // a margin for the skinned rest pose's world transform, which may scale it.
                    const Vec3 expected = plain.set.visemes[i].positions[v] - plain.set.neutral.positions[v];
                    const Vec3 delta = got.set.visemes[i].positions[v] - got.set.neutral.positions[v];
                    ASSERT_LE((delta - expected).norm(), 1.5 * std::sqrt(3.0) * step + 1e-6)
                        << "m=" << m << " " << plain.visemes[i] << " vertex " << v;
                }
        }
    }
}

} // namespace
} // namespace vl
