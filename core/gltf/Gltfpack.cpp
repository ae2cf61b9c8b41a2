#include "core/gltf/Gltfpack.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/gltf/GlbContainer.h"
#include "core/gltf/GltfDocument.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

extern char** environ;

namespace vl {
namespace {

using Json = nlohmann::ordered_json;
constexpr std::string_view kWhere = "gltfpack";

bool isExecutableFile(const std::filesystem::path& file) {
    std::error_code error;
    return std::filesystem::is_regular_file(file, error) && ::access(file.c_str(), X_OK) == 0;
}

std::string readBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The last `count` non-empty lines of a tool's output, joined by " / ".
std::string lastLines(const std::string& text, std::size_t count) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    std::string tail;
    for (std::size_t i = lines.size() > count ? lines.size() - count : 0; i < lines.size(); ++i)
        tail += (tail.empty() ? "" : " / ") + lines[i];
    return tail.empty() ? "no output" : tail;
}

// A private folder for gltfpack's input and output, removed when done.
struct TemporaryFolder {
    std::filesystem::path path;
    TemporaryFolder() {
        std::string pattern = (std::filesystem::temp_directory_path() / "visemelab-gltfpack-XXXXXX").string();
        if (!::mkdtemp(pattern.data()))
            throwInputError(kWhere, "cannot create a temporary folder in " + pattern);
        path = pattern;
    }
    ~TemporaryFolder() {
        std::error_code error;
        std::filesystem::remove_all(path, error);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
};

// Runs the program with its output (stdout and stderr) in `log`; returns the wait status.
int run(const std::filesystem::path& program, const std::vector<std::string>& arguments,
        const std::filesystem::path& log) {
    std::vector<char*> argv;
    std::string name = program.string();
    argv.push_back(name.data());
    std::vector<std::string> copies = arguments;
    for (std::string& argument : copies) argv.push_back(argument.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                     0600);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    pid_t pid = -1;
    const int spawned = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0)
        throwInputError(kWhere,
                        "cannot run " + program.string() + " (error " + std::to_string(spawned) + ")");
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) throwInputError(kWhere, "lost " + program.string() + " (waitpid failed)");
    return status;
}

// Named node -> the mesh it shows: its own, or (gltfpack) that of its only unnamed child with a mesh.
std::map<std::string, int> meshesByNodeName(const Json& document) {
    std::map<std::string, int> meshes;
    const Json nodes = document.value("nodes", Json::array());
    for (const Json& node : nodes) {
        if (!node.contains("name") || !node["name"].is_string()) continue;
        int mesh = node.value("mesh", -1);
        if (mesh < 0)
            for (const Json& child : node.value("children", Json::array())) {
                if (!child.is_number_unsigned() || child.get<std::size_t>() >= nodes.size()) continue;
                const Json& c = nodes[child.get<std::size_t>()];
                if (c.contains("name") || !c.contains("mesh")) continue;
                mesh = mesh < 0 ? c["mesh"].get<int>() : -2; // two: ambiguous
            }
        if (mesh >= 0) meshes.emplace(node["name"].get<std::string>(), mesh);
    }
    return meshes;
}

// Puts back what gltfpack drops: the document's extras, and each mesh's name and extras, found
// through the named node that places it. Refuses when a mesh with extras cannot be found.
std::string restore(const Json& before, std::string_view packedGlb, std::vector<std::string>& notes) {
    const GlbChunks chunks = splitGlb(packedGlb, "gltfpack output");
    Json after = Json::parse(chunks.json);
    if (before.contains("extras") && before["extras"].is_object()) {
        if (!after.contains("extras") || !after["extras"].is_object()) after["extras"] = Json::object();
        for (const auto& [key, value] : before["extras"].items()) after["extras"][key] = value;
    }
    const std::map<std::string, int> beforeMeshes = meshesByNodeName(before);
    const std::map<std::string, int> afterMeshes = meshesByNodeName(after);
    std::map<int, int> afterOf; // mesh before -> mesh after
    for (const auto& [name, mesh] : beforeMeshes) {
        const auto found = afterMeshes.find(name);
        if (found != afterMeshes.end()) afterOf.emplace(mesh, found->second);
    }
    const Json& meshesBefore = before["meshes"];
    Json& meshesAfter = after["meshes"];
    for (std::size_t m = 0; m < meshesBefore.size(); ++m) {
        const Json& mesh = meshesBefore[m];
        const bool hasExtras = mesh.contains("extras") && mesh["extras"].is_object();
        const auto found = afterOf.find(static_cast<int>(m));
        const std::string name = mesh.value("name", "mesh " + std::to_string(m));
        if (found == afterOf.end() || found->second < 0 ||
            static_cast<std::size_t>(found->second) >= meshesAfter.size()) {
            if (hasExtras)
                throwInputError(kWhere, "its output no longer tells which mesh is '" + name +
                                            "' (the node placing it has no name): the uncompressed avatar "
                                            "keeps its phoneme map, write that one");
            continue;
        }
        Json& target = meshesAfter[static_cast<std::size_t>(found->second)];
        if (mesh.contains("name")) target["name"] = mesh["name"];
        if (!hasExtras) continue;
        const auto targetCount = [](const Json& meshJson) {
            const Json primitives = meshJson.value("primitives", Json::array());
            return primitives.empty() ? std::size_t{0} : primitives[0].value("targets", Json::array()).size();
        };
        const std::size_t targetsBefore = targetCount(mesh), targetsAfter = targetCount(target);
        if (targetsBefore != targetsAfter)
            throwInputError(kWhere, "mesh '" + name + "' has " + std::to_string(targetsAfter) +
                                        " morph targets in its output, " + std::to_string(targetsBefore) +
                                        " before");
        if (target.contains("extras") && target["extras"].contains("targetNames") &&
            target["extras"]["targetNames"] != mesh["extras"].value("targetNames", Json()))
            throwInputError(kWhere, "re-ordered the morph targets of mesh '" + name + "'");
        target["extras"] = mesh["extras"];
    }
    notes.push_back("gltfpack re-orders meshes and places each on an unnamed child of the named node that "
                    "placed it; mesh names and VisemeLab's extras were put back");
    return joinGlb(after.dump(), chunks.bin);
}

} // namespace

std::filesystem::path findGltfpack() {
    if (const char* configured = std::getenv("VISEMELAB_GLTFPACK"); configured && *configured)
        return isExecutableFile(configured) ? std::filesystem::path(configured) : std::filesystem::path();
    const char* path = std::getenv("PATH");
    std::istringstream folders(path ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');) {
        if (folder.empty()) continue;
        const std::filesystem::path candidate = std::filesystem::path(folder) / "gltfpack";
        if (isExecutableFile(candidate)) return candidate;
    }
    return {};
}

Recompressed recompressWithGltfpack(const std::string& glb, const std::filesystem::path& gltfpack,
                                    const AvatarSelection& selection) {
    const GltfDocument input = parseGltfDocument(glb, "the reduced avatar", {});
    for (const char* vrm : {"VRM", "VRMC_vrm"})
        if (input.json.contains("extensions") && input.json["extensions"].contains(vrm))
            throwInputError(kWhere, std::string("a VRM is not re-compressed: gltfpack drops the ") + vrm +
                                        " extension, which refers to nodes, meshes and materials by the "
                                        "indices gltfpack renumbers");
    if (gltfpack.empty() || !isExecutableFile(gltfpack))
        throwInputError(
            kWhere, (gltfpack.empty() ? std::string("not found") : gltfpack.string() + " is not executable") +
                        ": " + kGltfpackHint);
    const TemporaryFolder folder;
    const auto in = folder.path / "reduced.glb", out = folder.path / "packed.glb",
               log = folder.path / "log.txt";
    writeFileAtomically(in, glb);
    // -c meshopt compression; -kn/-km keep named nodes and materials (clients find them by name);
    // -ke keeps extras where gltfpack can; -af 0 keeps the animations' own keyframes.
    const int status =
        run(gltfpack, {"-i", in.string(), "-o", out.string(), "-c", "-kn", "-km", "-ke", "-af", "0"}, log);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !std::filesystem::exists(out))
        throwInputError(kWhere, gltfpack.string() + " failed (" +
                                    (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                                       : std::string("killed by a signal")) +
                                    "): " + lastLines(readBytes(log), 3));
    Recompressed result;
    result.glb = restore(input.json, readBytes(out), result.notes);
    // The same visemes on the same meshes, read back by the same reader as any avatar.
    const AvatarScan before = scanAvatar(input, selection);
    const AvatarScan after = scanAvatar(parseGltfDocument(result.glb, "gltfpack output", {}), selection);
    const auto carriers = [](const AvatarScan& scan) {
        std::vector<std::string> names;
        for (const AvatarMesh& mesh : scan.meshes)
            if (mesh.carriesVisemes) names.push_back(mesh.name);
        std::sort(names.begin(), names.end());
        return names;
    };
    if (after.visemes != before.visemes || carriers(after) != carriers(before))
        throwInputError(kWhere, "its output does not yield the reduced avatar's visemes on the same meshes");
    result.notes.insert(result.notes.begin(), "re-compressed with gltfpack (EXT_meshopt_compression, "
                                              "KHR_mesh_quantization): " +
                                                  std::to_string(glb.size()) + " -> " +
                                                  std::to_string(result.glb.size()) + " bytes");
    return result;
}

void recompressInPlace(std::string& glb, std::vector<std::string>& notes,
                       const std::filesystem::path& gltfpack, const AvatarSelection& selection) {
    Recompressed packed = recompressWithGltfpack(glb, gltfpack, selection);
    glb = std::move(packed.glb);
    notes.insert(notes.end(), packed.notes.begin(), packed.notes.end());
}

} // namespace vl
