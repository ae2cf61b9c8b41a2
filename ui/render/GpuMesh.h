#pragma once
// A triangle mesh on the GPU with morph targets for live deformation (see shaders/mesh.vert):
// rest positions and normals as vertex attributes, per-target position and normal deltas in a
// texture buffer, an optional per-vertex scalar in [0,1] shown through the colour map, and optional
// materials (textures and base colours, GpuSurface) drawn in ColorMode::Material.
#include "core/mesh/Mesh.h"
#include "ui/render/GpuSurface.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace vl::ui {

class GlShader;

constexpr int kMaxMorphTargets = 128; // matches kMaxTargets in shaders/mesh.vert

// Material: the materials of setSurface (the surface colour where there are none).
enum class ColorMode { Surface, Scalar, VertexColor, Material };

struct DrawStyle {
    bool wireframe = true;
    ColorMode color = ColorMode::Surface; // Scalar: the per-vertex scalar through the colour map
    glm::vec3 surfaceColor{0.86f, 0.72f, 0.64f};
    glm::vec4 wireColor{0.10f, 0.10f, 0.12f, 0.35f};
    // Drawn as a flat translucent film of ghostColor over what is already drawn, where it lies on
    // or in front of it (depth tested, not written): an overlay of one shape on another.
    bool ghost = false;
    glm::vec4 ghostColor{0.25f, 0.80f, 1.0f, 0.45f};
};

// Positions as the caller holds them, never copied to build an argument (meshoptimizer's
// `vertex_positions` + `vertex_positions_stride`): `count` Vec3 values, value i at byte offset
// i * `stride` from `data` (stride in bytes, at least sizeof(Vec3); sizeof(Vec3) when packed). A
// span of Vec3 (a std::vector, a mesh's positions) converts to a packed view. The view does not
// own the positions: they must outlive the call it is passed to.
struct PositionSpan {
    const Vec3* data = nullptr;
    std::size_t count = 0;
    std::size_t stride = sizeof(Vec3);

    PositionSpan() = default;
    PositionSpan(std::span<const Vec3> packed)
        : data(packed.data()), count(packed.size()) {} // NOLINT: implicit
    PositionSpan(const std::vector<Vec3>& packed) : PositionSpan(std::span<const Vec3>(packed)) {} // NOLINT
    PositionSpan(const Vec3* first, std::size_t values, std::size_t byteStride)
        : data(first), count(values), stride(byteStride) {}
    std::size_t size() const { return count; }
    bool packed() const { return stride == sizeof(Vec3); }
    const Vec3& operator[](std::size_t i) const {
        return *reinterpret_cast<const Vec3*>(reinterpret_cast<const unsigned char*>(data) + i * stride);
    }
};

// Views of each element's positions, e.g. positionSpans(set.visemes, &Viseme::positions), or of
// each array of a range of position arrays: one small view per element, no position copied.
template <class Range, class Member>
std::vector<PositionSpan> positionSpans(const Range& elements, Member member) {
    std::vector<PositionSpan> views;
    views.reserve(std::size(elements));
    for (const auto& element : elements) views.emplace_back(element.*member);
    return views;
}
inline std::vector<PositionSpan> positionSpans(const std::vector<std::vector<Vec3>>& arrays) {
    return {arrays.begin(), arrays.end()};
}

// vertexNormals (core/mesh/Mesh.h) of positions given as a view: read in place when packed,
// gathered into a scratch array otherwise.
std::vector<Vec3> vertexNormals(PositionSpan positions, std::span<const Triangle> triangles);

class GpuMesh {
  public:
    GpuMesh() = default;
    ~GpuMesh();
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;

    // Uploads the rest shape and the targets (absolute positions, one view per target, each with
    // rest.size() entries), read where the caller holds them. Throws std::invalid_argument for
    // mismatched sizes, a stride below sizeof(Vec3) or too many targets.
    void setGeometry(PositionSpan rest, std::span<const Triangle> triangles,
                     std::span<const PositionSpan> targets);
    // One value in [0,1] per vertex, or empty to clear.
    void setScalars(std::span<const float> values);
    // One RGB colour in [0,1] per vertex, or empty for the surface colour everywhere.
    void setColors(std::span<const Vec3> colors);

    // Materials over the current geometry (cleared by setGeometry); throws std::invalid_argument
    // when the layout does not fit it.
    void setSurface(const SurfaceLayout& layout, const SurfaceMaterials& materials);
    bool hasSurface() const { return !surface_.empty(); }
    const GpuSurface& surface() const { return surface_; }

    // Weights beyond the targets of setGeometry are ignored; missing ones count as zero.
    void draw(const GlShader& shader, std::span<const float> weights, const glm::mat4& modelView,
              const glm::mat4& projection, const DrawStyle& style) const;

    bool empty() const { return triangleCount_ == 0; }
    std::size_t vertexCount() const { return rest_.size(); }
    std::size_t triangleCount() const { return triangleCount_; }
    // The positions the vertex shader produces for these weights (for picking and framing).
    std::vector<Vec3> blendedPositions(std::span<const float> weights) const;
    const std::vector<Triangle>& triangles() const { return triangles_; }

  private:
    void release();

    GLuint vao_ = 0, positionBuffer_ = 0, normalBuffer_ = 0, scalarBuffer_ = 0, colorBuffer_ = 0,
           indexBuffer_ = 0;
    GLuint targetBuffer_ = 0, targetTexture_ = 0;
    std::size_t triangleCount_ = 0;
    int targetCount_ = 0;
    std::vector<Vec3> rest_;
    std::vector<Triangle> triangles_;
    GpuSurface surface_;
    std::vector<float> deltas_;  // CPU copy of the position deltas, targetCount x vertexCount x 3
    std::uint64_t revision_ = 0; // changes with every upload (see SceneSignature)
};

} // namespace vl::ui
