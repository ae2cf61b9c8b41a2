#pragma once
// An interpolable viseme set: a neutral mesh (topology, (u,v), neutral positions) plus n named
// visemes that differ from it only in vertex positions. Which file a viseme came from is not part of
// the set: the document keeps it (Document::visemeFiles), loaders pass it to the checks below.
#include "core/mesh/Mesh.h"

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace vl {

struct Viseme {
    std::string name;
    std::vector<Vec3> positions; // one per vertex of the neutral mesh, same order
};

struct VisemeSet {
    MeshData neutral;
    std::filesystem::path neutralSource;
    std::vector<Viseme> visemes;

    std::size_t size() const { return visemes.size(); }
    std::size_t vertexCount() const { return neutral.positions.size(); }
    // Index of the viseme with this name, or -1.
    int find(std::string_view name) const;
    // The viseme as a full mesh (neutral topology and (u,v), the viseme's positions).
    MeshData meshOf(std::size_t viseme) const;
};

// A viseme set of large meshes as `reduce` holds it (docs/performance.md, issue 33): the visemes'
// positions as float32 x, y, z in one block (12 bytes a position, not 24, and no vector per viseme),
// the neutral as a mesh (weights, rest pose and the keys' topology need it whole).
// Precision: a float32 input file is held exactly. A double input (OBJ text, double PLY) is rounded
// once, each coordinate by a relative error u <= 2^-24; every sum over the positions is then
// accumulated in double (ShapeView.h), so a squared distance |a - b|^2 moves by at most
// 2u |a - b| (|a| + |b|) + u^2 (|a| + |b|)^2 from its value on the unrounded inputs: relative to it,
// about 2^-23 (|a| + |b|) / |a - b| (1.2e-7 times the coordinates' size over the distance).
struct FloatVisemeSet {
    MeshData neutral;
    std::filesystem::path neutralSource;
    std::vector<std::string> names;
    std::unique_ptr<float[]> positions; // names.size() x vertexCount() x 3, viseme after viseme

    std::size_t size() const { return names.size(); }
    std::size_t vertexCount() const { return neutral.positions.size(); }
    const float* visemePositions(std::size_t viseme) const {
        return positions.get() + 3 * viseme * vertexCount();
    }
};

// Throws InputError naming `otherSource` and the first mismatch (vertex count, face count, or the
// first differing face) when `other` is not interpolable with `reference`.
void checkInterpolable(const MeshData& reference, std::string_view referenceSource, const MeshData& other,
                       std::string_view otherSource);

// Throws InputError at `where` when a neutral and `visemeCount` visemes of `vertexCount` vertices
// each would hold more than limits::maxVisemeSetPositions() positions (from physical memory). Loaders call it
// before reading the visemes, so a file naming one mesh many times cannot exhaust memory.
void checkVisemeSetSize(std::size_t visemeCount, std::size_t vertexCount, std::string_view where);

// Coordinates beyond +-1e30 are refused: squared distances between them would overflow to infinity
// (a scale of 1e160 once gave "optimal cost 0 (proved)"), and keys are written as float32.
inline constexpr double kMaxVisemeCoordinate = 1e30;

// Throws InputError naming the mesh file (or `where` for embedded shapes) and the vertex when a
// coordinate of the set is beyond kMaxVisemeCoordinate or not finite, or naming the viseme when
// its name is not valid UTF-8 (shown escaped). `visemeFiles` holds the file each viseme was read
// from (empty paths, or no list at all, for generated or embedded shapes).
void checkVisemeSetValues(const VisemeSet& set, std::string_view where,
                          std::span<const std::filesystem::path> visemeFiles = {});
// The same checks for one shape (`source` names it in errors): coordinates, then the name.
void checkVisemeValues(std::span<const Vec3> positions, std::string_view source);
void checkVisemeValues(std::span<const float> xyz, std::string_view source);
void checkVisemeName(const std::string& name, std::string_view source);

} // namespace vl
