#pragma once
// A mesh's materials on the GPU (core/mesh/SurfaceMaterials.h), drawn by GpuMesh in
// ColorMode::Material: its own vertex array with one vertex per distinct (mesh vertex, texture
// coordinate) pair, so UV seams stay sharp while the mesh itself is never split; each such vertex
// names its mesh vertex (aSource), whose morph deltas the vertex shader fetches. One RGBA8 texture
// per image (mipmapped, repeating), and per material range one draw: opaque and masked ranges
// first, then the translucent (BLEND) ones without depth writes.
#include "core/mesh/SurfaceMaterials.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <span>
#include <vector>

namespace vl::ui {

class GlShader;

// Bytes of `count` elements, as glBufferData takes them.
inline GLsizeiptr glByteSize(std::size_t count, std::size_t elementSize) {
    return static_cast<GLsizeiptr>(count * elementSize);
}

class GpuSurface {
  public:
    GpuSurface() = default;
    ~GpuSurface();
    GpuSurface(const GpuSurface&) = delete;
    GpuSurface& operator=(const GpuSurface&) = delete;

    // Uploads the layout over a mesh of rest positions/normals and triangles (the mesh GpuMesh
    // holds). Throws std::invalid_argument when the layout does not fit the mesh.
    void upload(std::span<const Vec3> rest, std::span<const Vec3> restNormals,
                std::span<const Triangle> triangles, const SurfaceLayout& layout,
                const SurfaceMaterials& materials);
    void release();
    bool empty() const { return vao_ == 0; }

    // With the program in use and GpuMesh's uniforms and morph texture set.
    void draw(const GlShader& shader) const;

    std::size_t vertexCount() const { return vertexCount_; }

  private:
    struct Range {
        GLsizei first = 0, count = 0; // indices
        int material = -1;
    };
    void drawRange(const GlShader& shader, const Range& range) const;

    GLuint vao_ = 0, positionBuffer_ = 0, normalBuffer_ = 0, texCoordBuffer_ = 0, sourceBuffer_ = 0,
           indexBuffer_ = 0;
    std::vector<GLuint> textures_;
    std::vector<SurfaceMaterial> materials_;
    std::vector<Range> ranges_;
    std::size_t vertexCount_ = 0;
};

} // namespace vl::ui
