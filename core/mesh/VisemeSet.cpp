#include "core/mesh/VisemeSet.h"

#include "core/common/Error.h"
#include "core/common/Limits.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <cmath>

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

[[noreturn]] void throwCoordinateError(std::string_view source, std::size_t vertex, double c) {
    throwInputError(quoteInput(source), "vertex " + std::to_string(vertex + 1) + ": coordinate " +
                                            formatDouble(c) +
                                            " beyond +-1e30 (squared distances would overflow)");
}

std::string sourceOr(const std::filesystem::path& file, std::string_view where, std::string_view shape) {
    return file.empty() ? std::string(where) + ": " + std::string(shape) : file.string();
}

} // namespace

void checkVisemeValues(std::span<const Vec3> positions, std::string_view source) {
    for (std::size_t v = 0; v < positions.size(); ++v)
        for (const double c : {positions[v][0], positions[v][1], positions[v][2]})
            if (!(std::abs(c) <= kMaxVisemeCoordinate)) throwCoordinateError(source, v, c);
}

void checkVisemeValues(std::span<const float> xyz, std::string_view source) {
    for (std::size_t k = 0; k < xyz.size(); ++k)
        if (!(std::abs(static_cast<double>(xyz[k])) <= kMaxVisemeCoordinate)) // as the doubles are checked
            throwCoordinateError(source, k / 3, xyz[k]);
}

void checkVisemeName(const std::string& name, std::string_view source) {
    if (!isValidUtf8(name))
        throwInputError(quoteInput(source), "viseme name \"" + quoteInput(name) + "\" is not valid UTF-8");
}

void checkVisemeSetValues(const VisemeSet& set, std::string_view where,
                          std::span<const std::filesystem::path> visemeFiles) {
    checkVisemeValues(set.neutral.positions, sourceOr(set.neutralSource, where, "neutral"));
    for (std::size_t i = 0; i < set.visemes.size(); ++i) {
        const Viseme& viseme = set.visemes[i];
        const std::filesystem::path file = i < visemeFiles.size() ? visemeFiles[i] : std::filesystem::path();
        const std::string source = sourceOr(file, where, "viseme " + quoteInput(viseme.name));
        checkVisemeName(viseme.name, source);
        checkVisemeValues(viseme.positions, source);
    }
}

} // namespace vl
