#include "ui/render/GpuMesh.h"

#include "ui/render/GlShader.h"
#include "ui/render/SceneSignature.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace vl::ui {
namespace {

void appendVec3(std::vector<float>& out, const Vec3& v) {
    out.push_back(static_cast<float>(v[0]));
    out.push_back(static_cast<float>(v[1]));
    out.push_back(static_cast<float>(v[2]));
}

} // namespace

GpuMesh::~GpuMesh() {
    release();
}

void GpuMesh::release() {
    const GLuint buffers[] = {positionBuffer_, normalBuffer_, scalarBuffer_,
                              colorBuffer_,    indexBuffer_,  targetBuffer_};
    for (GLuint b : buffers)
        if (b) glDeleteBuffers(1, &b);
    if (targetTexture_) glDeleteTextures(1, &targetTexture_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
    vao_ = positionBuffer_ = normalBuffer_ = scalarBuffer_ = colorBuffer_ = indexBuffer_ = targetBuffer_ =
        targetTexture_ = 0;
    surface_.release();
    triangleCount_ = 0;
    targetCount_ = 0;
    revision_ = nextUploadRevision();
}

std::vector<Vec3> vertexNormals(PositionSpan positions, std::span<const Triangle> triangles) {
    if (positions.packed())
        return vl::vertexNormals(std::span<const Vec3>(positions.data, positions.count), triangles);
    std::vector<Vec3> gathered(positions.count);
    for (std::size_t i = 0; i < positions.count; ++i) gathered[i] = positions[i];
    return vl::vertexNormals(std::span<const Vec3>(gathered), triangles);
}

void GpuMesh::setGeometry(PositionSpan rest, std::span<const Triangle> triangles,
                          std::span<const PositionSpan> targets) {
    if (targets.size() > static_cast<std::size_t>(kMaxMorphTargets))
        throw std::invalid_argument("at most " + std::to_string(kMaxMorphTargets) +
                                    " morph targets can be shown");
    if (rest.stride < sizeof(Vec3)) throw std::invalid_argument("position stride below one position");
    for (const PositionSpan& target : targets) {
        if (target.size() != rest.size())
            throw std::invalid_argument("morph target size differs from the mesh");
        if (target.stride < sizeof(Vec3)) throw std::invalid_argument("position stride below one position");
    }
    release();
    rest_.resize(rest.size());
    for (std::size_t i = 0; i < rest.size(); ++i) rest_[i] = rest[i];
    triangles_.assign(triangles.begin(), triangles.end());

    const std::size_t n = rest.size();
    const std::vector<Vec3> restNormals = vl::vertexNormals(std::span<const Vec3>(rest_), triangles);
    std::vector<float> positions, normals;
    positions.reserve(3 * n);
    normals.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
        appendVec3(positions, rest_[i]);
        appendVec3(normals, restNormals[i]);
    }
    // Per target: n position deltas, then n normal deltas (layout read by mesh.vert).
    std::vector<float> texels;
    texels.reserve(targets.size() * 6 * n + 3);
    deltas_.clear();
    deltas_.reserve(targets.size() * 3 * n);
    for (const PositionSpan& target : targets) {
        const std::vector<Vec3> targetNormals = vertexNormals(target, triangles);
        for (std::size_t i = 0; i < n; ++i) {
            appendVec3(texels, target[i] - rest_[i]);
            appendVec3(deltas_, target[i] - rest_[i]);
        }
        for (std::size_t i = 0; i < n; ++i) appendVec3(texels, targetNormals[i] - restNormals[i]);
    }
    if (texels.empty()) texels.assign(3, 0.0f); // a texture buffer must not be empty

    glGenVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glGenBuffers(1, &positionBuffer_);
    glBindBuffer(GL_ARRAY_BUFFER, positionBuffer_);
    glBufferData(GL_ARRAY_BUFFER, glByteSize(positions.size(), sizeof(float)), positions.data(),
                 GL_STATIC_DRAW);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    glGenBuffers(1, &normalBuffer_);
    glBindBuffer(GL_ARRAY_BUFFER, normalBuffer_);
    glBufferData(GL_ARRAY_BUFFER, glByteSize(normals.size(), sizeof(float)), normals.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(1);
    glGenBuffers(1, &scalarBuffer_);
    glBindBuffer(GL_ARRAY_BUFFER, scalarBuffer_);
    const std::vector<float> zeros(n, 0.0f);
    glBufferData(GL_ARRAY_BUFFER, glByteSize(n, sizeof(float)), zeros.data(), GL_DYNAMIC_DRAW);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(2);
    glGenBuffers(1, &colorBuffer_);
    glBindBuffer(GL_ARRAY_BUFFER, colorBuffer_);
    const std::vector<float> grey(3 * n, 0.8f);
    glBufferData(GL_ARRAY_BUFFER, glByteSize(grey.size(), sizeof(float)), grey.data(), GL_DYNAMIC_DRAW);
    glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(3);
    glGenBuffers(1, &indexBuffer_);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_);
    static_assert(sizeof(Triangle) == 3 * sizeof(std::uint32_t));
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, glByteSize(triangles.size(), sizeof(Triangle)), triangles.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);

    glGenBuffers(1, &targetBuffer_);
    glBindBuffer(GL_TEXTURE_BUFFER, targetBuffer_);
    glBufferData(GL_TEXTURE_BUFFER, glByteSize(texels.size(), sizeof(float)), texels.data(), GL_STATIC_DRAW);
    glGenTextures(1, &targetTexture_);
    glBindTexture(GL_TEXTURE_BUFFER, targetTexture_);
    glTexBuffer(GL_TEXTURE_BUFFER, GL_RGB32F, targetBuffer_);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glBindBuffer(GL_TEXTURE_BUFFER, 0);

    triangleCount_ = triangles.size();
    targetCount_ = static_cast<int>(targets.size());
    revision_ = nextUploadRevision();
}

void GpuMesh::setSurface(const SurfaceLayout& layout, const SurfaceMaterials& materials) {
    surface_.release();
    if (!layout.empty())
        surface_.upload(rest_, vertexNormals(rest_, triangles_), triangles_, layout, materials);
    revision_ = nextUploadRevision();
}

void GpuMesh::setScalars(std::span<const float> values) {
    if (!scalarBuffer_) return;
    const std::size_t n = rest_.size();
    std::vector<float> data(n, 0.0f);
    std::copy_n(values.begin(), std::min(n, values.size()), data.begin());
    glBindBuffer(GL_ARRAY_BUFFER, scalarBuffer_);
    glBufferSubData(GL_ARRAY_BUFFER, 0, glByteSize(n, sizeof(float)), data.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    revision_ = nextUploadRevision();
}

void GpuMesh::setColors(std::span<const Vec3> colors) {
    if (!colorBuffer_) return;
    const std::size_t n = rest_.size();
    std::vector<float> data;
    data.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i) appendVec3(data, i < colors.size() ? colors[i] : Vec3(0.8, 0.8, 0.8));
    glBindBuffer(GL_ARRAY_BUFFER, colorBuffer_);
    glBufferSubData(GL_ARRAY_BUFFER, 0, glByteSize(data.size(), sizeof(float)), data.data());
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    revision_ = nextUploadRevision();
}

void GpuMesh::draw(const GlShader& shader, std::span<const float> weights, const glm::mat4& modelView,
                   const glm::mat4& projection, const DrawStyle& style) const {
    if (empty()) return;
    float uniformWeights[kMaxMorphTargets] = {};
    std::copy_n(weights.begin(),
                std::min<std::size_t>(weights.size(), static_cast<std::size_t>(targetCount_)),
                uniformWeights);
    if (SceneSignature* signature = SceneSignature::recording()) {
        // Everything this draw depends on; the GL state it sets is its own (see below).
        signature->addValue(this);
        signature->addValue(revision_);
        signature->add(uniformWeights, sizeof(float) * static_cast<std::size_t>(targetCount_));
        signature->addValue(modelView);
        signature->addValue(projection);
        signature->addValue(style.wireframe);
        signature->addValue(style.color);
        signature->addValue(style.surfaceColor);
        signature->addValue(style.wireColor);
        signature->addValue(style.ghost);
        signature->addValue(style.ghostColor);
        const GLuint program = shader.id();
        signature->addValue(program);
        return;
    }

    glUseProgram(shader.id());
    glUniformMatrix4fv(shader.uniform("uModelView"), 1, GL_FALSE, glm::value_ptr(modelView));
    glUniformMatrix4fv(shader.uniform("uProjection"), 1, GL_FALSE, glm::value_ptr(projection));
    glUniform1i(shader.uniform("uTargetCount"), targetCount_);
    glUniform1i(shader.uniform("uVertexCount"), static_cast<GLint>(rest_.size()));
    glUniform1fv(shader.uniform("uTargetWeights"), kMaxMorphTargets, uniformWeights);
    const bool material = style.color == ColorMode::Material && !surface_.empty();
    const ColorMode mode = style.color == ColorMode::Material && !material ? ColorMode::Surface : style.color;
    glUniform1i(shader.uniform("uColorMode"), static_cast<GLint>(mode));
    glUniform1i(shader.uniform("uUseSource"), 0);
    glUniform1i(shader.uniform("uBaseTexture"), 1); // never unit 0, the morph texture buffer's
    glUniform3fv(shader.uniform("uSurfaceColor"), 1, glm::value_ptr(style.surfaceColor));
    glUniform4fv(shader.uniform("uWireColor"), 1, glm::value_ptr(style.wireColor));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_BUFFER, targetTexture_);
    glUniform1i(shader.uniform("uTargets"), 0);

    glBindVertexArray(vao_);
    const auto indexCount = static_cast<GLsizei>(3 * triangleCount_);
    if (style.ghost) {
        // The line pass's flat colour, on the fill pass, blended; the same polygon offset as a normal
        // fill so where the shapes coincide the film shows (LEQUAL), and no depth writes.
        glUniform1i(shader.uniform("uWireframe"), 1);
        glUniform4fv(shader.uniform("uWireColor"), 1, glm::value_ptr(style.ghostColor));
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        glDepthFunc(GL_LEQUAL);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 1.0f);
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
        glBindVertexArray(0);
        glBindTexture(GL_TEXTURE_BUFFER, 0);
        glUseProgram(0);
        return;
    }
    // Fill pass pushed back slightly so the line pass sits on top without z-fighting.
    glUniform1i(shader.uniform("uWireframe"), 0);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    if (material) {
        surface_.draw(shader); // its own vertex array
        glBindVertexArray(vao_);
    } else {
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    if (style.wireframe) {
        glUniform1i(shader.uniform("uWireframe"), 1);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, nullptr);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDisable(GL_BLEND);
    }
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_BUFFER, 0);
    glUseProgram(0);
}

std::vector<Vec3> GpuMesh::blendedPositions(std::span<const float> weights) const {
    std::vector<Vec3> out = rest_;
    const std::size_t n = rest_.size();
    const std::size_t count = std::min<std::size_t>(weights.size(), static_cast<std::size_t>(targetCount_));
    for (std::size_t t = 0; t < count; ++t) {
        if (weights[t] == 0.0f) continue;
        const float* d = deltas_.data() + t * 3 * n;
        for (std::size_t i = 0; i < n; ++i)
            out[i] += Vec3(d[3 * i], d[3 * i + 1], d[3 * i + 2]) * static_cast<double>(weights[t]);
    }
    return out;
}

} // namespace vl::ui
