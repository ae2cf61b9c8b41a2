// Writes the generated part of the fuzz seed corpus (tests/fuzz/corpus/<target>/gen-*): small files
// made by the project's own writers, so the fuzzers start from every structure the readers accept
// (GLB and JSON glTF with data URIs, each avatar storage kind, runtime packages, Xface .fdp/.dic, a
// speech track). Run by hand after a format changes: `fuzz_seeds tests/fuzz/corpus`; the output is
// committed, the fuzz tests never write into the repository.
#include "core/common/AtomicFile.h"
#include "core/export/GltfExport.h"
#include "core/export/RuntimePackageWriter.h"
#include "core/export/Xface.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/GlbContainer.h"
#include "core/gltf/GltfDocument.h"
#include "core/speech/TrackJson.h"
#include "tests/export/TestModels.h"
#include "tests/gltf/AvatarFixtures.h"
#include "tests/gltf/KeyTableVersion1.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>

namespace {

namespace fs = std::filesystem;

std::string base64(std::string_view bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t group = 0;
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        for (std::size_t k = 0; k < 3; ++k)
            group = (group << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kDigits[(group >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// The JSON glTF form of a GLB: its BIN chunk as a base64 data URI of buffer 0.
std::string gltfWithDataUri(const std::string& glb) {
    const vl::GlbChunks chunks = vl::splitGlb(glb, "seed");
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(chunks.json);
    json["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(chunks.bin);
    return json.dump();
}

vl::SpeechTrackFile sampleTrack() {
    vl::SpeechTrackFile t;
    t.metadata = {"audio.wav", 0.7321, "Hi, you.", "", "en-us", 175, "sample.vlproj", "cubic", 30};
    t.mouthCues = {{0.0, 0.1 / 3, "sil"}, {0.1 / 3, 0.5, "aa"}, {0.5, 0.7321, "sil"}};
    t.reducedCues = {{0.0, 0.1 / 3, "sil+PP"}, {0.1 / 3, 0.7321, "aa"}};
    t.phonemes = {{"sil", 0.0, 0.1 / 3}, {"HH", 0.1 / 3, 0.2}, {"AY", 0.2, 0.5}, {"sil", 0.5, 0.7321}};
    t.error = vl::TrackError{1.25e-3, 0.017, 0.4, 0.031, {0.0, 1e-17, 0.017, 2.0 / 3}, {}};
    t.errorCurve = {{1, 102.5, 0.2, 1.5, 0.9}, {2, 20.1, 0.05, 0.9, 0.3}};
    return t;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s CORPUS_DIR (tests/fuzz/corpus)\n", argv[0]);
        return 2;
    }
    try {
        const fs::path dir = argv[1];
        auto write = [&](const std::string& target, const std::string& name, const std::string& bytes) {
            vl::writeFileAtomically(dir / target / ("gen-" + name), bytes);
        };
        const vl::ReducedModel model = vl::test::randomModel(4, 3, 3, true, 7);
        const std::string glb = vl::formatGlb(model);
        write("gltf_import", "model.glb", glb);
        write("gltf_import", "model.gltf", gltfWithDataUri(glb));
        write("gltf_import", "model_no_uv.glb", vl::formatGlb(vl::test::randomModel(3, 3, 2, false, 8)));

        using vl::test::FixtureStorage;
        const std::pair<const char*, FixtureStorage> kinds[] = {{"plain", FixtureStorage::Plain},
                                                                {"quantised", FixtureStorage::Quantised},
                                                                {"meshopt", FixtureStorage::Meshopt},
                                                                {"sparse", FixtureStorage::Sparse},
                                                                {"draco", FixtureStorage::Draco}};
        for (const auto& [name, storage] : kinds) {
            vl::test::AvatarFixtureOptions options;
            options.storage = storage;
            options.headColumns = 4;
            options.headRows = 3;
            options.teethColumns = 3;
            options.teethRows = 2;
            options.eyeSegments = 4;
            options.animation = storage == FixtureStorage::Plain;
            const std::string avatar = vl::test::rpmLikeAvatar(options);
            write("gltf_avatar", std::string("rpm_") + name + ".glb", avatar);
            if (storage != FixtureStorage::Plain) continue;
            write("gltf_avatar", "rpm_plain.gltf", gltfWithDataUri(avatar));
            // VisemeLab's own output (extras.visemelab, each mesh's visemeKeys and targetAliases), in
            // both name modes and both key table versions (core/gltf/KeyTable.h): the scan recognises
            // it, so the fuzzer mutates what that reads.
            const vl::GltfDocument doc = vl::parseGltfDocument(avatar, "seed", {});
            const vl::AvatarScan scan = vl::scanAvatar(doc, {});
            vl::ReduceSettings settings;
            settings.target = 4;
            settings.rest = vl::RestChoice::Free;
            const auto reduced = [&](vl::AvatarNames names) {
                return vl::reduceAvatar(doc, scan, vl::uniformFrequencies(scan), settings, {names}).glb;
            };
            const std::string merged = reduced(vl::AvatarNames::Merged);
            write("gltf_avatar", "rpm_plain_reduced_merged.glb", merged);
            write("gltf_avatar", "rpm_plain_reduced_original.glb", reduced(vl::AvatarNames::Original));
            write("gltf_avatar", "rpm_plain_reduced_merged_v1.glb", vl::test::withKeyTableVersion1(merged));
        }
        write("gltf_avatar", "vroid_vrm0.glb", vl::test::vroidLikeAvatar(false));

        int index = 0;
        for (bool quantise : {false, true})
            for (bool uvs : {false, true}) {
                ++index;
                write("runtime_package", "package" + std::to_string(index) + ".vlrt",
                      vl::encodeRuntimePackage(
                          vl::test::randomModel(4, 3, 3, uvs, 30 + static_cast<unsigned>(index)),
                          {.quantise = quantise}));
            }

        write("fdp", "face.fdp", vl::formatFdp(model));
        write("xface_dic", "face.dic", vl::formatXfaceDictionary(model));
        write("speech_track", "track.json", vl::formatTrackJson(sampleTrack()));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
