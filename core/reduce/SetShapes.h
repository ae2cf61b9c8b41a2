#pragma once
// A viseme set as the reduction reads it: the neutral mesh, the visemes' names in set order and a
// view of their shapes. One run (ReduceRun.h) serves both stores of a set: a VisemeSet (doubles, the
// editor and small sets) and a FloatVisemeSet (one float32 block, `reduce` of large meshes).
#include "core/mesh/VisemeSet.h"
#include "core/reduce/ShapeView.h"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct SetShapes {
    const MeshData* neutral = nullptr; // the set's neutral: it outlives the view
    std::vector<std::string> names;
    ShapeView shapes;

    std::size_t size() const { return names.size(); }
    // Index of the viseme with this name, or -1.
    int find(std::string_view name) const;
};

SetShapes shapesOf(const VisemeSet& set);
SetShapes shapesOf(const FloatVisemeSet& set);

// The key merging `members` as float32 x, y, z into `out` (3 per vertex), one key at a time for a
// writer: bit for bit the float32 of mergeGroup's doubles (the same sums in the same order), and a
// single member's own shape as buildReducedModel copies it.
void mergeKeyInto(const ShapeView& shapes, std::span<const double> frequencies, std::span<const int> members,
                  std::span<float> out);

} // namespace vl
