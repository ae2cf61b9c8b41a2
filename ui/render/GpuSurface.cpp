#include "ui/render/GpuSurface.h"

#include "ui/render/GlShader.h"
#include "ui/render/SeamSplit.h"

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <stdexcept>

namespace vl::ui {
namespace {

GLuint arrayBuffer(GLuint location, const std::vector<float>& data, int components) {
    GLuint buffer = 0;
    glGenBuffers(1, &buffer);
    glBindBuffer(GL_ARRAY_BUFFER, buffer);
    glBufferData(GL_ARRAY_BUFFER, glByteSize(data.size(), sizeof(float)), data.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(location);
    return buffer;
}

GLuint uploadImage(const TextureImage& image) {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 image.rgba.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

GLint glWrap(TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::Clamp:
        return GL_CLAMP_TO_EDGE;
    case TextureWrap::Mirror:
        return GL_MIRRORED_REPEAT;
    case TextureWrap::Repeat:
        break;
    }
    return GL_REPEAT;
}

// KHR_texture_transform's matrix: translation * rotation * scale (the extension's GLSL).
glm::mat3 texTransform(const SurfaceMaterial& m) {
    const float c = std::cos(m.uvRotation), s = std::sin(m.uvRotation);
    const glm::mat3 translation(1, 0, 0, 0, 1, 0, m.uvOffset[0], m.uvOffset[1], 1);
    const glm::mat3 rotation(c, s, 0, -s, c, 0, 0, 0, 1);
    const glm::mat3 scale(m.uvScale[0], 0, 0, 0, m.uvScale[1], 0, 0, 0, 1);
    return translation * rotation * scale;
}

} // namespace

GpuSurface::~GpuSurface() {
    release();
}

void GpuSurface::release() {
    const GLuint buffers[] = {positionBuffer_, normalBuffer_, texCoordBuffer_, sourceBuffer_, indexBuffer_};
    for (GLuint b : buffers)
        if (b) glDeleteBuffers(1, &b);
    if (!textures_.empty()) glDeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
    if (vao_) glDeleteVertexArrays(1, &vao_);
    vao_ = positionBuffer_ = normalBuffer_ = texCoordBuffer_ = sourceBuffer_ = indexBuffer_ = 0;
    textures_.clear();
    materials_.clear();
    ranges_.clear();
    vertexCount_ = 0;
}

void GpuSurface::upload(std::span<const Vec3> rest, std::span<const Vec3> restNormals,
                        std::span<const Triangle> triangles, const SurfaceLayout& layout,
                        const SurfaceMaterials& materials) {
    release();
    if (layout.empty()) return;
    std::size_t covered = 0;
    for (const MaterialRange& r : layout.ranges) {
        if (r.firstTriangle != covered || r.material < -1 ||
            r.material >= static_cast<int>(materials.materials.size()))
            throw std::invalid_argument("material ranges do not cover the mesh in order");
        covered += r.triangleCount;
    }
    if (covered != triangles.size()) throw std::invalid_argument("material ranges do not cover the mesh");

    const SeamSplit split = splitAtSeams(triangles, rest.size(), layout);
    const bool texCoords = !layout.cornerTexCoords.empty();
    std::vector<float> positions, normals, uvs;
    std::vector<std::int32_t> sources;
    for (std::size_t d = 0; d < split.source.size(); ++d) {
        const std::uint32_t v = split.source[d];
        for (int a = 0; a < 3; ++a) {
            positions.push_back(static_cast<float>(rest[v][a]));
            normals.push_back(static_cast<float>(restNormals[v][a]));
        }
        const Vec2 uv = texCoords ? layout.texCoords[split.texCoord[d]] : Vec2(0, 0);
        uvs.push_back(static_cast<float>(uv[0]));
        uvs.push_back(static_cast<float>(uv[1]));
        sources.push_back(static_cast<std::int32_t>(v));
    }
    const std::vector<std::uint32_t>& indices = split.indices;

    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    positionBuffer_ = arrayBuffer(0, positions, 3);
    normalBuffer_ = arrayBuffer(1, normals, 3);
    texCoordBuffer_ = arrayBuffer(4, uvs, 2);
    glGenBuffers(1, &sourceBuffer_);
    glBindBuffer(GL_ARRAY_BUFFER, sourceBuffer_);
    glBufferData(GL_ARRAY_BUFFER, glByteSize(sources.size(), sizeof(std::int32_t)), sources.data(),
                 GL_STATIC_DRAW);
    glVertexAttribIPointer(5, 1, GL_INT, 0, nullptr);
    glEnableVertexAttribArray(5);
    glGenBuffers(1, &indexBuffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, glByteSize(indices.size(), sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    for (const TextureImage& image : materials.images) textures_.push_back(uploadImage(image));
    materials_ = materials.materials;
    for (const MaterialRange& r : layout.ranges)
        ranges_.push_back({static_cast<GLsizei>(3 * r.firstTriangle),
                           static_cast<GLsizei>(3 * r.triangleCount), r.material});
    vertexCount_ = sources.size();
}

void GpuSurface::drawRange(const GlShader& shader, const Range& range) const {
    SurfaceMaterial plain; // no material: white
    const SurfaceMaterial& m =
        range.material >= 0 ? materials_[static_cast<std::size_t>(range.material)] : plain;
    // The factor is linear (glTF); the shader works in display values like the texture's texels.
    const glm::vec4 colour(std::pow(m.baseColor[0], 1.0f / 2.2f), std::pow(m.baseColor[1], 1.0f / 2.2f),
                           std::pow(m.baseColor[2], 1.0f / 2.2f), m.baseColor[3]);
    glUniform4fv(shader.uniform("uBaseColor"), 1, glm::value_ptr(colour));
    const bool textured = m.image >= 0 && static_cast<std::size_t>(m.image) < textures_.size();
    glUniform1i(shader.uniform("uHasTexture"), textured ? 1 : 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, textured ? textures_[static_cast<std::size_t>(m.image)] : 0);
    if (textured) { // the material's sampler (one image may be sampled differently by two materials)
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, glWrap(m.wrapU));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, glWrap(m.wrapV));
    }
    glActiveTexture(GL_TEXTURE0);
    const glm::mat3 transform = texTransform(m);
    glUniformMatrix3fv(shader.uniform("uTexTransform"), 1, GL_FALSE, glm::value_ptr(transform));
    glUniform1i(shader.uniform("uAlphaMode"), static_cast<GLint>(m.alphaMode));
    glUniform1f(shader.uniform("uAlphaCutoff"), m.alphaCutoff);
    glDrawElements(
        GL_TRIANGLES, range.count, GL_UNSIGNED_INT,
        reinterpret_cast<const void*>(static_cast<std::uintptr_t>(range.first) * sizeof(std::uint32_t)));
}

void GpuSurface::draw(const GlShader& shader) const {
    if (empty()) return;
    glBindVertexArray(vao_);
    glUniform1i(shader.uniform("uUseSource"), 1);
    const auto blended = [&](const Range& r) {
        return r.material >= 0 &&
               materials_[static_cast<std::size_t>(r.material)].alphaMode == AlphaMode::Blend;
    };
    for (const Range& r : ranges_)
        if (!blended(r)) drawRange(shader, r);
    // Translucent surfaces (eyelashes, eye films) over what is opaque, without hiding each other.
    // The view's alpha stays opaque (ImGui blends the view's image over the window by it).
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    for (const Range& r : ranges_)
        if (blended(r)) drawRange(shader, r);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glUniform1i(shader.uniform("uUseSource"), 0);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, 0);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(0);
}

} // namespace vl::ui
