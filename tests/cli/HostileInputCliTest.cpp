// A catalogue of hostile inputs, one per class of attack docs/robustness.md lists, each given to the
// command that reads it: every run ends in exit code 3 (data error) or 2 (an output that is an input)
// with a message naming the file, within 20 s of CPU and (outside sanitizer builds) 1.5 GiB of address
// space, and leaves every input byte for byte as it was and no temporaries behind.
#include "CliRunner.h"
#include "tests/cli/SanitizerBuild.h"

#include "core/common/AtomicFile.h"
#include "core/gltf/GlbContainer.h"
#include "core/io/MeshIO.h"
#include "tests/export/TestModels.h"
#include "tests/gltf/AvatarFixtures.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sys/stat.h>

namespace vl {
namespace {

namespace fs = std::filesystem;

constexpr bool kAddressSanitizer = test::kAddressSanitizer;

struct HostileCase {
    std::string name; // the test's name
    std::string file; // the hostile file's name in the scratch folder
    std::function<void(const fs::path& file)> make;
    std::string command; // {file} is the hostile file, {dir} the scratch folder
    int exitCode = 3;
};

// A `make` writing these bytes (computed when the test runs).
std::function<void(const fs::path&)> bytes(std::function<std::string()> contents) {
    return [contents](const fs::path& file) { std::ofstream(file, std::ios::binary) << contents(); };
}

std::string nested(std::size_t depth) {
    return std::string(depth, '[') + std::string(depth, ']');
}

std::string editedAvatar(const std::function<void(nlohmann::ordered_json&)>& edit, int headColumns = 4,
                         int headRows = 3) {
    test::AvatarFixtureOptions options;
    options.headColumns = headColumns;
    options.headRows = headRows;
    options.animation = false;
    const std::string glb = test::rpmLikeAvatar(options);
    const GlbChunks chunks = splitGlb(glb, "fixture");
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(chunks.json);
    edit(json);
    return joinGlb(json.dump(), chunks.bin);
}

// The head mesh's first primitive repeated: every copy uses the same accessors.
void repeatHeadPrimitive(nlohmann::ordered_json& json, std::size_t copies) {
    for (auto& mesh : json["meshes"])
        if (mesh["name"] == "Wolf3D_Head") mesh["primitives"] = std::vector(copies, mesh["primitives"][0]);
}

// A JSON array of `count` empty objects (3 bytes each).
std::string emptyObjects(std::size_t count) {
    std::string s = "[";
    for (std::size_t i = 0; i < count; ++i) s += i ? ",{}" : "{}";
    return s + "]";
}

// Reduce commands reading one hostile file beside good meshes.
const std::string kReduceMesh =
    "reduce --neutral {file} --viseme a={dir}/a.obj --viseme b={dir}/b.obj -m 1 --out {dir}/out";
const std::string kReduceWith =
    "reduce --neutral {dir}/n.obj --viseme a={dir}/a.obj --viseme b={dir}/b.obj -m 1 --out {dir}/out ";

std::vector<HostileCase> catalogue() {
    const std::string vrmlBomb = [] {
        std::string s = "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord DEF C Coordinate { point [";
        for (int i = 0; i < 20000; ++i) s += " 0 0 0,";
        s += "] } coordIndex [0 1 2] } }\n";
        for (int i = 0; i < 4000; ++i)
            s += "Shape { geometry IndexedFaceSet { coord USE C coordIndex [0 1 2] } }\n";
        return s;
    }();
    return {
        {"ObjTruncated", "n.obj", bytes([] { return std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2"); }),
         kReduceMesh},
        {"ObjHugeForwardIndex", "n.obj", bytes([] { return std::string("v 0 0 0\nf 1 2 4000000000\n"); }),
         kReduceMesh},
        {"ObjNaN", "n.obj", bytes([] { return std::string("v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }),
         kReduceMesh},
        {"ObjOverflowingNumber", "n.obj",
         bytes([] { return std::string("v 1e999 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }), kReduceMesh},
        {"PlyHugeDeclaredCount", "n.ply", bytes([] {
             return std::string(
                        "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty float x\n"
                        "property float y\nproperty float z\nelement face 4000000000\n"
                        "property list uchar int vertex_indices\nend_header\n") +
                    std::string(64, '\0');
         }),
         kReduceMesh},
        {"PlyHugeListLength", "n.ply", bytes([] {
             return std::string(
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 1\nproperty list uint int vertex_indices\n"
                 "end_header\n0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n");
         }),
         kReduceMesh},
        {"VrmlUseAmplification", "n.wrl", bytes([vrmlBomb] { return vrmlBomb; }), kReduceMesh},
        {"DirectoryAsMesh", "n.obj",
         [](const fs::path& file) {
             fs::remove(file);
             fs::create_directory(file);
         },
         kReduceMesh},
        {"ProjectDeeplyNested", "p.vlproj", bytes([] {
             return "{\"format\": \"visemelab-project\", \"version\": 1, \"x\": " + nested(1000000) + "}";
         }),
         "project check {file}"},
        {"FrequenciesOverflowToInfinity", "f.json",
         bytes([] { return std::string(R"({"a": 1e999, "b": 1})"); }), kReduceWith + "--freq-file {file}"},
        {"FrequenciesDeeplyNested", "f.json", bytes([] { return "{\"a\": " + nested(200000) + "}"; }),
         kReduceWith + "--freq-file {file}"},
        {"FrequenciesManyDuplicates", "f.csv", bytes([] {
             std::string s;
             for (int i = 0; i < 100000; ++i) s += "p" + std::to_string(i) + ",1\n";
             return s + "p0,2\n";
         }),
         kReduceWith + "--freq-file {file}"},
        {"MapDeeplyNested", "m.json", bytes([] { return "{\"map\": " + nested(200000) + "}"; }),
         kReduceWith + "--freq-file {dir}/phonemes.csv --map {file}"},
        {"WeightsDeeplyNested", "w.json", bytes([] { return "[1, 2, " + nested(200000) + "]"; }),
         kReduceWith + "--weights {file}"},
        {"WeightsOverflow", "w.txt", bytes([] { return std::string("1\n1e999\n1\n"); }),
         kReduceWith + "--weights {file}"},
        {"FdpMalformed", "face.fdp",
         bytes([] { return std::string("<xfdp><source><entity alias=\"Rest\"><mesh file="); }),
         "reduce --fdp {file} -m 1 --out {dir}/out"},
        {"GlbHugeAccessorCount", "a.glb",
         bytes([] { return editedAvatar([](auto& json) { json["accessors"][0]["count"] = 4000000000u; }); }),
         "avatar inspect {file}"},
        {"GlbSparseIndicesOfAFloatType", "a.glb", bytes([] {
             return editedAvatar([](auto& json) {
                 json["accessors"][0]["sparse"] = {{"count", 1},
                                                   {"indices", {{"bufferView", 0}, {"componentType", 5126}}},
                                                   {"values", {{"bufferView", 0}}}};
             });
         }),
         "avatar inspect {file}"},
        {"GlbDeeplyNestedExtras", "a.glb", bytes([] {
             const std::string glb = editedAvatar([](auto&) {});
             const GlbChunks chunks = splitGlb(glb, "fixture");
             std::string json(chunks.json);
             json.insert(json.find('{') + 1, "\"extras\": " + nested(100000) + ",");
             return joinGlb(json, chunks.bin);
         }),
         "avatar inspect {file}"},
        {"GltfUriOutsideItsFolder", "a.gltf", bytes([] {
             return std::string(
                 R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "../../../../etc/passwd", )"
                 R"("byteLength": 12}]})");
         }),
         "avatar inspect {file}"},
        {"GlbTruncated", "a.glb", bytes([] { return editedAvatar([](auto&) {}).substr(0, 1000); }),
         "avatar inspect {file}"},
        // Issue 30: JSON that the old parser took quadratic time over (23 s, 44 s), memory amplified
        // by shared accessors, overflow after node transforms.
        {"ProjectOfManyEmptyObjects", "p.vlproj", bytes([] {
             return "{\"format\": \"visemelab-project\", \"version\": 1, \"x\": " + emptyObjects(400000) +
                    "}";
         }),
         "project check {file}"},
        {"ProjectHugeObjectWithADuplicateKey", "p.vlproj", bytes([] {
             std::string s = "{";
             for (int i = 0; i < 100000; ++i) s += "\"k" + std::to_string(i) + "\": {},";
             return s + "\"k7\": 1}";
         }),
         "project check {file}"},
        {"ProjectWithAMegabyteKey", "p.vlproj", bytes([] {
             return "{\"format\": \"visemelab-project\", \"" + std::string(6000000, 'k') + "\": 1}";
         }),
         "project check {file}"},
        {"FrequenciesOfManyEmptyObjects", "f.json",
         bytes([] { return "{\"a\": " + emptyObjects(400000) + "}"; }), kReduceWith + "--freq-file {file}"},
        {"GlbExtrasOfManyEmptyObjects", "a.glb", bytes([] {
             return editedAvatar(
                 [](auto& json) { json["extras"] = nlohmann::ordered_json::parse(emptyObjects(400000)); });
         }),
         "avatar inspect {file}", 0},
        {"GlbOneAccessorUsedByThousandsOfPrimitives", "a.glb",
         bytes([] { return editedAvatar([](auto& json) { repeatHeadPrimitive(json, 3000); }, 100, 100); }),
         "avatar inspect {file}"},
        {"GlbNodeScaleOverflowingSquares", "a.glb", bytes([] {
             return editedAvatar([](auto& json) {
                 for (auto& node : json["nodes"])
                     if (node["name"] == "Armature") node["scale"] = {1e160, 1e160, 1e160};
             });
         }),
         "avatar inspect {file}"},
        {"ObjCoordinatesOverflowingSquares", "n.obj",
         bytes([] { return std::string("v 1e160 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }), kReduceMesh},
        // Names that are not UTF-8, symlink loops and special files: exit 3 naming the culprit, never
        // "internal error" (exit 1) and never a reader blocked on a FIFO or reading /dev/zero forever.
        {"VisemeNameNotUtf8InArgv", "a.obj", [](const fs::path&) {},
         kReduceMesh.substr(0, kReduceMesh.find(" --viseme")) +
             "/n.obj --viseme \"$(printf 'x\\377')\"={file} "
             "--viseme b={dir}/b.obj -m 1 --out {dir}/out"},
        {"VisemeFileNameNotUtf8InAFolder", "v",
         [](const fs::path& folder) {
             fs::create_directory(folder);
             for (const char* name : {"n.obj", "b.obj", "\xff\xfe.obj"})
                 fs::copy_file(folder.parent_path() / "a.obj", folder / name);
         },
         "reduce --neutral {file}/n.obj --visemes {file} -m 1 --out {dir}/out"},
        {"FrequencyCsvNameNotUtf8", "f.csv", bytes([] { return std::string("phoneme,count\n\xff\xfe,3\n"); }),
         kReduceWith + "--freq-file {file}"},
        {"SymlinkLoopAsMesh", "n.obj",
         [](const fs::path& file) {
             fs::remove(file);
             fs::create_symlink(file.filename(), file);
         },
         kReduceMesh},
        {"SymlinkLoopInAVisemeFolder", "v",
         [](const fs::path& folder) {
             fs::create_directory(folder);
             fs::copy_file(folder.parent_path() / "a.obj", folder / "n.obj");
             fs::create_symlink("l2.obj", folder / "l1.obj");
             fs::create_symlink("l1.obj", folder / "l2.obj");
         },
         "reduce --neutral {file}/n.obj --visemes {file} -m 1 --out {dir}/out"},
        {"DevZeroAsMesh", "n.obj",
         [](const fs::path& file) {
             fs::remove(file);
             fs::create_symlink("/dev/zero", file);
         },
         kReduceMesh},
        {"FifoAsMesh", "n.obj",
         [](const fs::path& file) {
             fs::remove(file);
             ::mkfifo(file.c_str(), 0600);
         },
         kReduceMesh},
        {"FifoAsProject", "p.vlproj", [](const fs::path& file) { ::mkfifo(file.c_str(), 0600); },
         "project check {file}"},
        {"ReportOntoTheNeutralMesh", "n.obj", [](const fs::path&) {}, kReduceWith + "--report {file}", 2},
        {"ReportThroughASymlinkToAnInput", "link.json",
         [](const fs::path& file) { fs::create_symlink(file.parent_path() / "a.obj", file); },
         kReduceWith + "--report {file}", 2},
    };
}

class HostileInput : public ::testing::TestWithParam<HostileCase> {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("visemelab_hostile_" + GetParam().name);
        fs::remove_all(dir);
        fs::create_directories(dir);
        const ReducedModel shapes = test::randomModel(4, 3, 2, false, 11, 0.1);
        writeMesh(dir / "n.obj", shapes.neutral);
        for (std::size_t k = 0; k < 2; ++k) {
            MeshData mesh = shapes.neutral;
            mesh.positions = shapes.keys[k].positions;
            writeMesh(dir / (k == 0 ? "a.obj" : "b.obj"), mesh);
        }
        std::ofstream(dir / "phonemes.csv") << "phoneme,count\nAA,3\nB,1\n";
    }
    void TearDown() override { fs::remove_all(dir); }

    std::map<std::string, std::string> snapshot() const {
        std::map<std::string, std::string> files;
        std::error_code ec; // symlink loops and FIFOs among the hostile files are not inputs to compare
        for (const auto& entry : fs::recursive_directory_iterator(dir))
            if (entry.is_regular_file(ec) && !entry.is_symlink(ec))
                files[entry.path().string()] = readFileToString(entry.path());
        return files;
    }

    fs::path dir;
};

TEST_P(HostileInput, EndsInADataErrorNamingTheFileWithinBoundsAndTouchesNoInput) {
    const HostileCase& c = GetParam();
    const fs::path file = dir / c.file;
    c.make(file);
    const auto before = snapshot();

    std::string command = c.command;
    for (std::string::size_type at; (at = command.find("{file}")) != std::string::npos;)
        command.replace(at, 6, file.string());
    for (std::string::size_type at; (at = command.find("{dir}")) != std::string::npos;)
        command.replace(at, 5, dir.string());
    // 20 s of CPU; 1.5 GiB of address space where no sanitizer reserves its shadow memory.
    const std::string limits =
        std::string("ulimit -t 20; ") + (kAddressSanitizer ? "" : "ulimit -v 1572864; ");
    const test::CliResult r = test::runCliWith(limits, command);

    EXPECT_EQ(r.exitCode, c.exitCode) << r.output.substr(0, 4000);
    // Input is quoted shortened (a 6 MB line once went to stderr whole).
    if (c.exitCode != 0) {
        EXPECT_LT(r.output.size(), 2000u) << r.output.substr(0, 4000);
    }
    EXPECT_NE(r.output.find(file.filename().string()), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("internal error"), std::string::npos) << r.output;
    EXPECT_EQ(snapshot(), before) << "an input changed or a file was written";
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        EXPECT_FALSE(entry.path().filename().string().starts_with(".")) << "left behind: " << entry.path();
}

INSTANTIATE_TEST_SUITE_P(Catalogue, HostileInput, ::testing::ValuesIn(catalogue()),
                         [](const auto& test) { return test.param.name; });

} // namespace
} // namespace vl
