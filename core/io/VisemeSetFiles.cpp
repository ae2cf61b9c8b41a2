#include "core/io/VisemeSetFiles.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/io/MeshIO.h"
#include "core/io/PlyFastPath.h"

#include <algorithm>
#include <cctype>
#include <unordered_set>

namespace vl {

namespace {

void requireTwoVisemes(const std::filesystem::path& neutral, std::size_t count) {
    if (count < 2)
        throwInputError("viseme set of " + neutral.string(),
                        "needs at least 2 visemes besides the neutral mesh, got " + std::to_string(count));
}

void requireNewName(std::unordered_set<std::string>& names, const std::string& name,
                    const std::filesystem::path& file) {
    if (name.empty()) throwInputError(file.string(), "viseme has an empty name");
    if (!names.insert(name).second) throwInputError(file.string(), "duplicate viseme name '" + name + "'");
}

// A binary float32 PLY of the neutral's layout straight into `out`, its faces compared (no doubles).
// `bytes` is reused from file to file.
bool readFloatsLike(const std::filesystem::path& file, const ReferenceMesh& reference, std::span<float> out,
                    FileBytes& bytes) {
    if (meshFormatFromPath(file) != MeshFormat::Ply || !reference.mesh.uvs.empty()) return false;
    readFileBytesInto(file, bytes);
    const std::string_view view = bytes.view();
    if (view.empty()) return false; // the general reader reports it
    return meshio::readPlyFloatsMatching(view, meshio::parsePlyHeader(view, file.string()),
                                         reference.mesh.triangles, out);
}

} // namespace

FloatVisemeSet loadFloatVisemeSet(const std::filesystem::path& neutral,
                                  const std::vector<std::pair<std::string, std::filesystem::path>>& visemes) {
    requireTwoVisemes(neutral, visemes.size());
    return loadFloatVisemeSet(neutral, readReferenceMesh(neutral), visemes);
}

FloatVisemeSet loadFloatVisemeSet(const std::filesystem::path& neutral, ReferenceMesh reference,
                                  const std::vector<std::pair<std::string, std::filesystem::path>>& visemes) {
    requireTwoVisemes(neutral, visemes.size());
    FloatVisemeSet set;
    set.neutralSource = neutral;
    const MeshData& neutralMesh = reference.mesh; // moved into the set at the end: never held twice
    const std::string where = "viseme set of " + neutral.string();
    checkVisemeSetSize(visemes.size(), neutralMesh.positions.size(), where);
    checkVisemeValues(neutralMesh.positions, neutral.string());
    const std::size_t floats = 3 * neutralMesh.positions.size();
    set.positions = std::make_unique_for_overwrite<float[]>(visemes.size() * floats); // every float is read
    std::unordered_set<std::string> names;
    FileBytes bytes;
    for (std::size_t i = 0; i < visemes.size(); ++i) {
        const auto& [name, file] = visemes[i];
        requireNewName(names, name, file);
        checkVisemeName(name, file.string());
        const std::span<float> out(set.positions.get() + i * floats, floats);
        if (!readFloatsLike(file, reference, out, bytes)) {
            MeshLike read = readPositionsLike(file, reference);
            if (!read.sameTopology)
                checkInterpolable(neutralMesh, neutral.string(), read.mesh, file.string());
            checkVisemeValues(read.mesh.positions,
                              file.string()); // before rounding: beyond float32 is refused
            for (std::size_t v = 0; v < read.mesh.positions.size(); ++v)
                for (int axis = 0; axis < 3; ++axis)
                    out[3 * v + static_cast<std::size_t>(axis)] =
                        static_cast<float>(read.mesh.positions[v][axis]);
        }
        checkVisemeValues(out, file.string());
        set.names.push_back(name);
    }
    set.neutral = std::move(reference.mesh);
    return set;
}

VisemeSet loadVisemeSet(const std::filesystem::path& neutral,
                        const std::vector<std::pair<std::string, std::filesystem::path>>& visemes) {
    requireTwoVisemes(neutral, visemes.size());
    return loadVisemeSet(neutral, readReferenceMesh(neutral), visemes);
}

VisemeSet loadVisemeSet(const std::filesystem::path& neutral, ReferenceMesh reference,
                        const std::vector<std::pair<std::string, std::filesystem::path>>& visemes) {
    requireTwoVisemes(neutral, visemes.size());
    VisemeSet set;
    set.neutralSource = neutral;
    set.neutral = reference.mesh;
    checkVisemeSetSize(visemes.size(), set.vertexCount(), "viseme set of " + neutral.string());
    std::unordered_set<std::string> names;
    std::vector<std::filesystem::path> files;
    for (const auto& [name, file] : visemes) {
        requireNewName(names, name, file);
        // Parses only the positions of a typical export, whose faces are then the neutral's.
        MeshLike read = readPositionsLike(file, reference);
        if (!read.sameTopology) checkInterpolable(set.neutral, neutral.string(), read.mesh, file.string());
        set.visemes.push_back({name, std::move(read.mesh.positions)});
        files.push_back(file);
    }
    checkVisemeSetValues(set, "viseme set of " + neutral.string(), files);
    return set;
}

std::vector<std::pair<std::string, std::filesystem::path>>
listVisemeFolder(const std::filesystem::path& folder, const std::filesystem::path& excluded) {
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) throwInputError(folder.string(), "not a folder");
    noteInputFolder(folder); // its files are inputs, and outputs must not go into it
    std::vector<std::filesystem::path> files;
    // A symlink loop or a dangling link in the folder is not a mesh (is_regular_file would throw).
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
        if (std::error_code fileError; entry.is_regular_file(fileError) && isMeshFile(entry.path()))
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    std::vector<std::pair<std::string, std::filesystem::path>> result;
    for (const auto& file : files) {
        if (!excluded.empty() && std::filesystem::equivalent(file, excluded, ec)) continue;
        result.emplace_back(file.stem().string(), file);
        noteInputFile(file); // named as an input even by commands that do not read it (project new)
    }
    if (result.empty()) throwInputError(folder.string(), "contains no mesh files (.obj, .ply, .wrl)");
    return result;
}

std::filesystem::path findNeutralMesh(const std::filesystem::path& folder) {
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) throwInputError(folder.string(), "not a folder");
    std::vector<std::filesystem::path> exact, containing;
    for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
        std::error_code fileError;
        if (!entry.is_regular_file(fileError) || !isMeshFile(entry.path())) continue;
        std::string stem = entry.path().stem().string();
        std::transform(stem.begin(), stem.end(), stem.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (stem == "neutral")
            exact.push_back(entry.path());
        else if (stem.find("neutral") != std::string::npos)
            containing.push_back(entry.path());
    }
    const std::vector<std::filesystem::path>& found = exact.empty() ? containing : exact;
    if (found.empty())
        throwInputError(folder.string(),
                        "no neutral mesh in the folder (a mesh file named neutral.obj, "
                        ".ply or .wrl, or with 'neutral' in its name); give it with --neutral");
    if (found.size() > 1) {
        std::vector<std::string> names;
        for (const auto& file : found) names.push_back(file.filename().string());
        std::sort(names.begin(), names.end());
        std::string list;
        for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
        throwInputError(folder.string(),
                        "several meshes could be the neutral (" + list + "); give it with --neutral");
    }
    return found.front();
}

} // namespace vl
