#include "core/reduce/VisemeSet.h"

#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/Limits.h"
#include "core/common/TextParsing.h"
#include "core/io/MeshIO.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <unordered_set>

namespace vl {

int VisemeSet::find(std::string_view name) const {
    for (std::size_t i = 0; i < visemes.size(); ++i)
        if (visemes[i].name == name) return static_cast<int>(i);
    return -1;
}

MeshData VisemeSet::meshOf(std::size_t viseme) const {
    MeshData mesh = neutral;
    mesh.positions = visemes.at(viseme).positions;
    return mesh;
}

void checkInterpolable(const MeshData& reference, std::string_view referenceSource, const MeshData& other,
                       std::string_view otherSource) {
    const std::string against = " (the neutral mesh " + std::string(referenceSource) + " has ";
    if (other.positions.size() != reference.positions.size())
        throwInputError(otherSource, "not interpolable: " + std::to_string(other.positions.size()) +
                                         " vertices" + against + std::to_string(reference.positions.size()) +
                                         ")");
    if (other.triangles.size() != reference.triangles.size())
        throwInputError(otherSource, "not interpolable: " + std::to_string(other.triangles.size()) +
                                         " triangles" + against + std::to_string(reference.triangles.size()) +
                                         ")");
    const auto mismatch =
        std::mismatch(reference.triangles.begin(), reference.triangles.end(), other.triangles.begin());
    if (mismatch.first != reference.triangles.end()) {
        const auto face = static_cast<std::size_t>(mismatch.first - reference.triangles.begin());
        const auto& a = *mismatch.first;
        const auto& b = *mismatch.second;
        auto text = [](const Triangle& t) {
            return std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]);
        };
        throwInputError(otherSource, "not interpolable: triangle " + std::to_string(face) + " is (" +
                                         text(b) + ") but (" + text(a) + ") in the neutral mesh " +
                                         std::string(referenceSource));
    }
}

void checkVisemeSetSize(std::size_t visemeCount, std::size_t vertexCount, std::string_view where) {
    if (visemeCount > limits::kMaxVisemes)
        throwInputError(where, "too many visemes: " + std::to_string(visemeCount) + " (at most " +
                                   std::to_string(limits::kMaxVisemes) + ")");
    const std::size_t limit = limits::maxVisemeSetPositions();
    if (vertexCount > limit || visemeCount + 1 > limit / std::max<std::size_t>(vertexCount, 1))
        throwInputError(where, "too large: " + std::to_string(visemeCount) + " visemes of " +
                                   std::to_string(vertexCount) +
                                   " vertices (plus the neutral) exceed the limit of " +
                                   std::to_string(limit) +
                                   " vertex positions in one viseme set (half this machine's physical "
                                   "memory at " +
                                   std::to_string(limits::kVisemeSetBytesPerPosition) + " bytes a position)");
}

namespace {

void checkCoordinates(std::span<const Vec3> positions, const std::string& source) {
    for (std::size_t v = 0; v < positions.size(); ++v)
        for (const double c : {positions[v][0], positions[v][1], positions[v][2]})
            if (!(std::abs(c) <= kMaxVisemeCoordinate))
                throwInputError(quoteInput(source), "vertex " + std::to_string(v + 1) + ": coordinate " +
                                                        formatDouble(c) +
                                                        " beyond +-1e30 (squared distances would overflow)");
}

std::string sourceOr(const std::filesystem::path& file, std::string_view where, std::string_view shape) {
    return file.empty() ? std::string(where) + ": " + std::string(shape) : file.string();
}

} // namespace

void checkVisemeSetValues(const VisemeSet& set, std::string_view where) {
    checkCoordinates(set.neutral.positions, sourceOr(set.neutralSource, where, "neutral"));
    for (const Viseme& viseme : set.visemes) {
        const std::string source = sourceOr(viseme.source, where, "viseme " + quoteInput(viseme.name));
        if (!isValidUtf8(viseme.name))
            throwInputError(quoteInput(source),
                            "viseme name \"" + quoteInput(viseme.name) + "\" is not valid UTF-8");
        checkCoordinates(viseme.positions, source);
    }
}

VisemeSet loadVisemeSet(const std::filesystem::path& neutral,
                        const std::vector<std::pair<std::string, std::filesystem::path>>& visemes) {
    if (visemes.size() < 2)
        throwInputError("viseme set of " + neutral.string(),
                        "needs at least 2 visemes besides the neutral mesh, got " +
                            std::to_string(visemes.size()));
    VisemeSet set;
    set.neutralSource = neutral;
    ReferenceMesh reference = readReferenceMesh(neutral);
    set.neutral = reference.mesh;
    checkVisemeSetSize(visemes.size(), set.vertexCount(), "viseme set of " + neutral.string());
    std::unordered_set<std::string> names;
    for (const auto& [name, file] : visemes) {
        if (name.empty()) throwInputError(file.string(), "viseme has an empty name");
        if (!names.insert(name).second)
            throwInputError(file.string(), "duplicate viseme name '" + name + "'");
        // Parses only the positions of a typical export, whose faces are then the neutral's.
        MeshLike read = readPositionsLike(file, reference);
        if (!read.sameTopology) checkInterpolable(set.neutral, neutral.string(), read.mesh, file.string());
        set.visemes.push_back({name, file, std::move(read.mesh.positions)});
    }
    checkVisemeSetValues(set, "viseme set of " + neutral.string());
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
