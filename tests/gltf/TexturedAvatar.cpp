#include "tests/gltf/TexturedAvatar.h"

#include "tests/common/TestImages.h"
#include "tests/gltf/GlbBuilder.h"

#include <vector>

namespace vl::test {
namespace {

using Json = nlohmann::ordered_json;

struct Grid {
    std::vector<float> positions, uvs;
    std::vector<std::uint32_t> indices;
};

// n x n vertices over [x0, x0 + size] x [y0, y0 + size] at depth z, (u,v) over [0,1] with v down.
Grid grid(int n, float x0, float y0, float size, float z) {
    Grid g;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            const float u = static_cast<float>(c) / static_cast<float>(n - 1);
            const float v = static_cast<float>(r) / static_cast<float>(n - 1);
            g.positions.insert(g.positions.end(), {x0 + size * u, y0 + size * (1.0f - v), z});
            g.uvs.insert(g.uvs.end(), {u, v});
        }
    for (int r = 0; r + 1 < n; ++r)
        for (int c = 0; c + 1 < n; ++c) {
            const auto i = static_cast<std::uint32_t>(r * n + c), w = static_cast<std::uint32_t>(n);
            g.indices.insert(g.indices.end(), {i, i + w, i + 1, i + 1, i + w, i + w + 1});
        }
    return g;
}

// A displacement of the grid's lower half downwards (a mouth opening), scaled.
std::vector<float> lowerHalfDown(const Grid& g, float amount) {
    std::vector<float> d(g.positions.size(), 0.0f);
    for (std::size_t v = 0; v < g.positions.size() / 3; ++v)
        if (g.positions[3 * v + 1] < 0.0f) d[3 * v + 1] = -amount * (0.0f - g.positions[3 * v + 1]);
    return d;
}

int addMesh(GlbBuilder& b, const std::string& name, const Grid& g, const Json& attributes, int material,
            const std::vector<std::pair<std::string, std::vector<float>>>& targets) {
    Json prim{{"attributes", attributes}, {"indices", b.addIndices(g.indices)}, {"material", material}};
    Json mesh{{"name", name}};
    if (!targets.empty()) {
        Json list = Json::array(), names = Json::array();
        for (const auto& [target, delta] : targets) {
            list.push_back({{"POSITION", b.addFloats(delta, "VEC3", true)}});
            names.push_back(target);
        }
        prim["targets"] = list;
        mesh["extras"] = {{"targetNames", names}};
        mesh["weights"] = std::vector<double>(targets.size(), 0.0);
    }
    mesh["primitives"] = Json::array({prim});
    const int index = b.add("meshes", mesh);
    return b.add("nodes", {{"name", name}, {"mesh", index}});
}

} // namespace

std::string texturedAvatar(const TexturedAvatarOptions& options) {
    GlbBuilder b;
    b.useExtension("KHR_texture_transform", false);
    b.useExtension("KHR_texture_basisu", false);
    const auto& c = options.faceColour;
    std::string png = pngBytes(4, 4, solidRgba(4, 4, c[0], c[1], c[2]));
    if (options.claimedSize) png = pngClaiming(options.claimedSize, options.claimedSize);
    Json image{{"name", "face_baseColor"}, {"mimeType", "image/png"}};
    if (options.externalImage)
        image["uri"] = "face.png";
    else
        image["bufferView"] = b.addView(png.data(), png.size());
    const int faceImage = b.add("images", image);
    const int clamp = b.add("samplers", {{"wrapS", 33071}, {"wrapT", 33071}});
    const int faceTexture = b.add("textures", {{"source", faceImage}, {"sampler", clamp}});
    const int faceMaterial =
        b.add("materials", {{"name", "Face"},
                            {"pbrMetallicRoughness",
                             {{"baseColorTexture",
                               {{"index", faceTexture},
                                {"texCoord", 0},
                                {"extensions",
                                 {{"KHR_texture_transform",
                                   {{"texCoord", 1}, {"offset", {0.5, 0.0}}, {"scale", {0.5, 1.0}}}}}}}}}}});
    const int eyeMaterial =
        b.add("materials", {{"name", "Eye"},
                            {"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 0.0, 0.0, 0.5}}}},
                            {"alphaMode", "BLEND"},
                            {"doubleSided", true}});
    const std::string ktx2 = std::string("\xABKTX 20\xBB\r\n\x1a\n", 12) + std::string(20, '\0');
    const int bodyImage =
        b.add("images", {{"bufferView", b.addView(ktx2.data(), ktx2.size())}, {"mimeType", "image/ktx2"}});
    const int bodyTexture =
        b.add("textures", {{"extensions", {{"KHR_texture_basisu", {{"source", bodyImage}}}}}});
    const int bodyMaterial =
        b.add("materials",
              {{"name", "Body"},
               {"pbrMetallicRoughness",
                {{"baseColorFactor", {0.2, 0.4, 0.6, 1.0}}, {"baseColorTexture", {{"index", bodyTexture}}}}},
               {"alphaMode", "MASK"},
               {"alphaCutoff", 0.25}});

    const Grid face = grid(9, -0.5f, -0.5f, 1.0f, 0.0f);
    std::vector<float> faceUv1 = face.uvs; // TEXCOORD_1: the set the texture reads
    for (float& v : faceUv1) v = 1.0f - v;
    const int faceNode = addMesh(b, "Face", face,
                                 {{"POSITION", b.addFloats(face.positions, "VEC3", true)},
                                  {"TEXCOORD_0", b.addFloats(face.uvs, "VEC2", false)},
                                  {"TEXCOORD_1", b.addFloats(faceUv1, "VEC2", false)}},
                                 faceMaterial,
                                 {{"viseme_sil", std::vector<float>(face.positions.size(), 0.0f)},
                                  {"viseme_aa", lowerHalfDown(face, 0.3f)},
                                  {"viseme_O", lowerHalfDown(face, 0.15f)}});
    const Grid eye = grid(2, 0.15f, 0.15f, 0.2f, 0.05f);
    const int eyeNode = addMesh(b, "Eye", eye, {{"POSITION", b.addFloats(eye.positions, "VEC3", true)}},
                                eyeMaterial, {{"viseme_aa", std::vector<float>(eye.positions.size(), 0.0f)}});
    const Grid body = grid(2, -0.8f, -1.6f, 1.6f, -0.1f);
    const int bodyNode = addMesh(b, "Body", body,
                                 {{"POSITION", b.addFloats(body.positions, "VEC3", true)},
                                  {"TEXCOORD_0", b.addFloats(body.uvs, "VEC2", false)}},
                                 bodyMaterial, {});
    b.add("scenes", {{"nodes", {faceNode, eyeNode, bodyNode}}});
    b.json["scene"] = 0;
    return b.glb();
}

} // namespace vl::test
