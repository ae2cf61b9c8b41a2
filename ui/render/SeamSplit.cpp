#include "ui/render/SeamSplit.h"

#include <stdexcept>
#include <string>
#include <unordered_map>

namespace vl::ui {

SeamSplit splitAtSeams(std::span<const Triangle> triangles, std::size_t vertexCount,
                       const SurfaceLayout& layout) {
    const bool texCoords = !layout.cornerTexCoords.empty();
    if (texCoords && layout.cornerTexCoords.size() != triangles.size())
        throw std::invalid_argument("texture coordinates of " +
                                    std::to_string(layout.cornerTexCoords.size()) +
                                    " triangles for a mesh of " + std::to_string(triangles.size()));
    SeamSplit out;
    out.indices.reserve(3 * triangles.size());
    // A glTF mesh maps one to one (its vertices are split at seams already): a hash map, not a
    // search, keeps that linear.
    std::unordered_map<std::uint64_t, std::uint32_t> drawnOf;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t v = triangles[t][k];
            const std::uint32_t c = texCoords ? layout.cornerTexCoords[t][k] : 0;
            if (v >= vertexCount || (texCoords && c >= layout.texCoords.size()))
                throw std::invalid_argument("triangle " + std::to_string(t) + " indexes beyond the mesh");
            const auto [it, added] =
                drawnOf.emplace(std::uint64_t{v} << 32 | c, static_cast<std::uint32_t>(out.source.size()));
            if (added) {
                out.source.push_back(v);
                out.texCoord.push_back(c);
            }
            out.indices.push_back(it->second);
        }
    return out;
}

} // namespace vl::ui
