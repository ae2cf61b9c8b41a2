#include "tests/gltf/AvatarFixtures.h"

#include "tests/gltf/GlbBuilder.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <meshoptimizer.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <map>
#include <random>
#include <stdexcept>
#include <tuple>

namespace vl::test {
namespace {

using Json = nlohmann::ordered_json;

// One primitive's data: float attributes per vertex, indices, named POSITION targets (deltas).
struct Part {
    std::vector<float> positions, normals, uvs;
    std::vector<std::uint32_t> indices;
    std::vector<std::pair<std::string, std::vector<float>>> targets;
    std::vector<std::uint8_t> joints; // 4 per vertex (skinned parts)
    std::vector<float> weights;       // 4 per vertex

    std::size_t vertices() const { return positions.size() / 3; }
};

glm::dvec3 at(const std::vector<float>& v, std::size_t i) {
    return {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
}

std::vector<float> computeNormals(const std::vector<float>& positions,
                                  const std::vector<std::uint32_t>& indices) {
    std::vector<glm::dvec3> n(positions.size() / 3, glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 a = at(positions, indices[t]), b = at(positions, indices[t + 1]),
                         c = at(positions, indices[t + 2]);
        const glm::dvec3 face = glm::cross(b - a, c - a);
        for (int k = 0; k < 3; ++k) n[indices[t + static_cast<std::size_t>(k)]] += face;
    }
    std::vector<float> out;
    for (const glm::dvec3& v : n) {
        const glm::dvec3 u = glm::length(v) > 1e-20 ? glm::normalize(v) : glm::dvec3(0, 0, 1);
        out.insert(out.end(), {static_cast<float>(u.x), static_cast<float>(u.y), static_cast<float>(u.z)});
    }
    return out;
}

// A columns x rows grid over (u, v) in [0,1]^2 mapped by `place`, counter-clockwise seen from outside.
template <typename Place> Part grid(int columns, int rows, Place place) {
    Part part;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            const double u = c / double(columns - 1), v = r / double(rows - 1);
            const glm::dvec3 p = place(u, v);
            part.positions.insert(part.positions.end(), {static_cast<float>(p.x), static_cast<float>(p.y),
                                                         static_cast<float>(p.z)});
            part.uvs.insert(part.uvs.end(), {static_cast<float>(u), static_cast<float>(1.0 - v)});
        }
    for (int r = 0; r + 1 < rows; ++r)
        for (int c = 0; c + 1 < columns; ++c) {
            const auto i = static_cast<std::uint32_t>(r * columns + c),
                       w = static_cast<std::uint32_t>(columns);
            part.indices.insert(part.indices.end(), {i, i + 1, i + w + 1, i, i + w + 1, i + w});
        }
    part.normals = computeNormals(part.positions, part.indices);
    return part;
}

// ---- The head and its shapes -------------------------------------------------------------

const glm::dvec3 kHeadCentre(0.0, 1.62, 0.0), kHeadRadii(0.075, 0.11, 0.09);
const glm::dvec3 kMouth =
    kHeadCentre + glm::dvec3(0.0, kHeadRadii.y* std::sin(-0.35), kHeadRadii.z* std::cos(-0.35));
const glm::dvec3 kEyeCentres[2] = {{0.032, 1.655, 0.068}, {-0.032, 1.655, 0.068}};

// Mouth movements the visemes mix: open (jaw down), round (lips forward and in), spread (corners
// out), press (lips together). Coefficients per Oculus viseme, sil ... ou.
struct Mix {
    double open, round, spread, press;
};
const Mix kVisemeMix[15] = {{0, 0, 0, 0},      {0, 0, 0.05, 1.0}, {0.1, 0, 0.2, 0.5}, {0.3, 0, 0.2, 0},
                            {0.35, 0, 0.3, 0}, {0.4, 0, 0.2, 0},  {0.3, 0.6, 0, 0},   {0.15, 0, 0.6, 0},
                            {0.3, 0, 0.25, 0}, {0.25, 0.5, 0, 0}, {1.0, 0, 0.2, 0},   {0.6, 0, 0.6, 0},
                            {0.4, 0, 0.7, 0},  {0.7, 0.8, 0, 0},  {0.3, 1.0, 0, 0}};

glm::dvec3 mouthMotion(const glm::dvec3& p, const Mix& m) {
    const double w = std::exp(-glm::dot(p - kMouth, p - kMouth) / (0.028 * 0.028));
    const double below = p.y < kMouth.y ? 1.0 : 0.15;
    const glm::dvec3 open(0, -0.014 * below, 0.0);
    const glm::dvec3 round((kMouth.x - p.x) * 0.35, 0.0, 0.008);
    const glm::dvec3 spread((p.x - kMouth.x) * 0.3, 0.001, -0.003);
    const glm::dvec3 press(0, p.y < kMouth.y ? 0.004 : -0.004, 0.002);
    return w * (m.open * open + m.round * round + m.spread * spread + m.press * press);
}

std::vector<float> field(const Part& part, const std::function<glm::dvec3(const glm::dvec3&)>& f) {
    std::vector<float> out;
    for (std::size_t i = 0; i < part.vertices(); ++i) {
        const glm::dvec3 d = f(at(part.positions, i));
        out.insert(out.end(), {static_cast<float>(d.x), static_cast<float>(d.y), static_cast<float>(d.z)});
    }
    return out;
}

Part headPart(const AvatarFixtureOptions& o) {
    Part head = grid(o.headColumns, o.headRows, [](double u, double v) {
        const double theta = (u - 0.5) * 1.6 * M_PI, phi = (v - 0.5) * 0.95 * M_PI;
        return kHeadCentre + glm::dvec3(kHeadRadii.x * std::cos(phi) * std::sin(theta),
                                        kHeadRadii.y * std::sin(phi),
                                        kHeadRadii.z * std::cos(phi) * std::cos(theta));
    });
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> noise(-1.0, 1.0);
    auto bump = [&](glm::dvec3 centre, glm::dvec3 move, double radius) {
        return field(head, [=](const glm::dvec3& p) {
            return move * std::exp(-glm::dot(p - centre, p - centre) / (radius * radius));
        });
    };
    head.targets.emplace_back("browInnerUp",
                              bump(kHeadCentre + glm::dvec3(0, 0.055, 0.07), {0, 0.006, 0}, 0.02));
    head.targets.emplace_back("jawOpen", field(head, [](const glm::dvec3& p) {
                                  return mouthMotion(p, {1.1, 0, 0, 0});
                              }));
    const auto names = rpmVisemeNames();
    for (std::size_t i = 0; i < names.size(); ++i) {
        // A little of each viseme's own, so that no two are exactly alike.
        const glm::dvec3 own(noise(rng), noise(rng), noise(rng));
        if (i == 0 && !o.restTarget) continue;
        head.targets.emplace_back(
            names[i], field(head, [&](const glm::dvec3& p) {
                return mouthMotion(p, kVisemeMix[i]) +
                       (i == 0 ? glm::dvec3(0.0) : 0.0008 * own * mouthMotion(p, {1, 0, 0, 0}).y / -0.014);
            }));
    }
    head.targets.emplace_back("mouthSmileLeft",
                              bump(kMouth + glm::dvec3(0.025, 0, -0.01), {0.004, 0.004, 0}, 0.015));
    head.targets.emplace_back("mouthSmileRight",
                              bump(kMouth + glm::dvec3(-0.025, 0, -0.01), {-0.004, 0.004, 0}, 0.015));
    head.targets.emplace_back("eyeBlinkLeft",
                              bump(kEyeCentres[0] + glm::dvec3(0, 0.01, 0.01), {0, -0.008, 0}, 0.012));
    head.targets.emplace_back("eyeBlinkRight",
                              bump(kEyeCentres[1] + glm::dvec3(0, 0.01, 0.01), {0, -0.008, 0}, 0.012));
    return head;
}

Part teethPart(const AvatarFixtureOptions& o) {
    Part teeth = grid(o.teethColumns, o.teethRows, [](double u, double v) {
        const double angle = (u - 0.5) * 1.4;
        return kMouth +
               glm::dvec3(0.022 * std::sin(angle), -0.012 + 0.018 * v, -0.012 - 0.01 * (1 - std::cos(angle)));
    });
    const auto lower = [](const glm::dvec3& p, double open) {
        return p.y < kMouth.y - 0.003 ? glm::dvec3(0, -0.014 * open, 0) : glm::dvec3(0.0);
    };
    teeth.targets.emplace_back("jawOpen", field(teeth, [&](const glm::dvec3& p) { return lower(p, 1.1); }));
    const auto names = rpmVisemeNames();
    for (std::size_t i = o.restTarget ? 0 : 1; i < names.size(); ++i)
        teeth.targets.emplace_back(
            names[i], field(teeth, [&](const glm::dvec3& p) { return lower(p, kVisemeMix[i].open); }));
    return teeth;
}

// An eye in its own frame (centred on the origin); its node places it.
Part eyePart(const AvatarFixtureOptions& o) {
    Part eye = grid(o.eyeSegments, std::max(3, o.eyeSegments / 2), [](double u, double v) {
        const double theta = u * 2 * M_PI, phi = (v - 0.5) * 0.9 * M_PI;
        return 0.012 *
               glm::dvec3(std::cos(phi) * std::sin(theta), std::sin(phi), std::cos(phi) * std::cos(theta));
    });
    for (const std::string& name : rpmVisemeNames())
        if (o.restTarget || name != "viseme_sil")
            eye.targets.emplace_back(name, std::vector<float>(eye.positions.size(), 0.0f));
    eye.targets.emplace_back(
        "eyesLookUp", field(eye, [](const glm::dvec3& p) { return glm::dvec3(0, p.z * 0.2, -p.y * 0.2); }));
    return eye;
}

Part bodyPart() {
    return grid(16, 6, [](double u, double v) {
        const double theta = u * 2 * M_PI;
        return glm::dvec3(0.15 * std::sin(theta), 0.9 + 0.58 * v, 0.1 * std::cos(theta));
    });
}

// ---- Skeleton ------------------------------------------------------------------------------

struct Skeleton {
    std::vector<int> jointNodes;       // Hips, Spine, Neck, Head
    std::vector<glm::dmat4> bindWorld; // joint world matrices at bind time
    int armature = -1, head = -1, neck = -1;
};

// Armature (rotated 90 degrees about X and scaled 0.01, as FBX conversions write it) with
// Hips > Spine > Neck > Head. The Head joint is turned 8 degrees about Y in the stored pose, so
// that the stored pose differs from the bind pose the inverse bind matrices describe.
Skeleton addSkeleton(GlbBuilder& b) {
    Skeleton s;
    const glm::dquat armatureRotation = glm::angleAxis(M_PI / 2, glm::dvec3(1, 0, 0));
    const glm::dmat4 armature =
        glm::mat4_cast(armatureRotation) * glm::scale(glm::dmat4(1.0), glm::dvec3(0.01));
    const glm::dvec3 jointWorld[4] = {{0, 0.95, 0}, {0, 1.2, 0}, {0, 1.48, 0}, {0, 1.56, 0}};
    const char* names[4] = {"Hips", "Spine", "Neck", "Head"};
    s.armature =
        b.add("nodes",
              {{"name", "Armature"},
               {"rotation", {armatureRotation.x, armatureRotation.y, armatureRotation.z, armatureRotation.w}},
               {"scale", {0.01, 0.01, 0.01}},
               {"extras", {{"exporter", "fixture"}}}});
    glm::dmat4 parentWorld = armature;
    int parent = s.armature;
    for (int j = 0; j < 4; ++j) {
        // Joint frames keep the armature's orientation and scale: local translation only.
        const glm::dvec3 local = glm::dvec3(glm::inverse(parentWorld) * glm::dvec4(jointWorld[j], 1.0));
        Json node{{"name", names[j]}, {"translation", {local.x, local.y, local.z}}};
        glm::dmat4 world = parentWorld * glm::translate(glm::dmat4(1.0), local);
        s.bindWorld.push_back(world);
        if (j == 3) {
            const glm::dquat turn = glm::angleAxis(8.0 * M_PI / 180.0, glm::dvec3(0, 0, 1)); // Y in world
            node["rotation"] = {turn.x, turn.y, turn.z, turn.w};
        }
        const int index = b.add("nodes", node);
        b.json["nodes"][static_cast<std::size_t>(parent)]["children"].push_back(index);
        s.jointNodes.push_back(index);
        parentWorld = world;
        parent = index;
    }
    s.neck = s.jointNodes[2];
    s.head = s.jointNodes[3];
    return s;
}

glm::dmat4 storedHeadWorld(const Skeleton& s) {
    const glm::dquat turn = glm::angleAxis(8.0 * M_PI / 180.0, glm::dvec3(0, 0, 1));
    return s.bindWorld[3] * glm::mat4_cast(turn);
}

void setSkinWeights(Part& part, int mainJoint, int otherJoint, double otherBelowY) {
    for (std::size_t i = 0; i < part.vertices(); ++i) {
        const bool blend = at(part.positions, i).y < otherBelowY;
        part.joints.insert(part.joints.end(), {static_cast<std::uint8_t>(mainJoint),
                                               static_cast<std::uint8_t>(blend ? otherJoint : 0), 0, 0});
        part.weights.insert(part.weights.end(), {blend ? 0.7f : 1.0f, blend ? 0.3f : 0.0f, 0.0f, 0.0f});
    }
}

// ---- Storage -------------------------------------------------------------------------------

std::vector<float> exponentialFiltered(const std::vector<float>& values,
                                       std::vector<unsigned char>& encoded) {
    encoded.resize(values.size() * 4);
    meshopt_encodeFilterExp(encoded.data(), values.size() / 3, 12, 15, values.data());
    std::vector<float> decoded(values.size());
    std::memcpy(decoded.data(), encoded.data(), encoded.size());
    meshopt_decodeFilterExp(decoded.data(), values.size() / 3, 12);
    return decoded;
}

int meshoptFloats(GlbBuilder& b, const std::vector<float>& values, const std::string& type, bool bounds,
                  bool exponential) {
    const std::size_t components = type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
    std::vector<double> lo, hi;
    int view;
    if (exponential) {
        std::vector<unsigned char> encoded;
        const std::vector<float> decoded = exponentialFiltered(values, encoded);
        view = b.addMeshoptView(encoded.data(), values.size() / 3, 12, "ATTRIBUTES", "EXPONENTIAL",
                                kArrayBuffer);
        if (bounds) vectorBounds(decoded, 3, lo, hi);
    } else {
        view = b.addMeshoptView(values.data(), values.size() / components, components * 4, "ATTRIBUTES",
                                "NONE", kArrayBuffer);
        if (bounds) vectorBounds(values, static_cast<int>(components), lo, hi);
    }
    return b.addAccessor(view, kFloat, type, values.size() / components, false, lo, hi);
}

// Unit normals as 8-bit octahedral (meshopt filter), read back as BYTE normalised VEC3
// (KHR_mesh_quantization).
int meshoptNormals(GlbBuilder& b, const std::vector<float>& normals) {
    std::vector<float> four;
    for (std::size_t i = 0; i < normals.size() / 3; ++i)
        four.insert(four.end(), {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2], 0.0f});
    std::vector<unsigned char> encoded(four.size());
    meshopt_encodeFilterOct(encoded.data(), normals.size() / 3, 4, 8, four.data());
    const int view =
        b.addMeshoptView(encoded.data(), normals.size() / 3, 4, "ATTRIBUTES", "OCTAHEDRAL", kArrayBuffer);
    return b.addAccessor(view, kByte, "VEC3", normals.size() / 3, true);
}

// Normalised shorts in [-1, 1] of (v - offset) / scale, 8-byte stride (4-byte element alignment).
int quantisedShorts(GlbBuilder& b, const std::vector<float>& values, glm::dvec3 offset, glm::dvec3 scale,
                    bool bounds) {
    std::vector<std::int16_t> q;
    std::vector<double> lo(3, 1e9), hi(3, -1e9);
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t c = i % 3;
        const double v = (values[i] - offset[static_cast<int>(c)]) / scale[static_cast<int>(c)];
        const auto s = static_cast<std::int16_t>(std::lround(std::clamp(v, -1.0, 1.0) * 32767.0));
        q.push_back(s);
        lo[c] = std::min<double>(lo[c], s); // min/max of integer accessors hold the stored integers
        hi[c] = std::max<double>(hi[c], s);
        if (c == 2) q.push_back(0);
    }
    const int view = b.addView(q.data(), q.size() * 2, kArrayBuffer, 8);
    if (!bounds) lo.clear(), hi.clear();
    return b.addAccessor(view, kShort, "VEC3", values.size() / 3, true, lo, hi);
}

struct Placement {
    glm::dvec3 offset{0.0}, scale{1.0}; // quantised storage: position = offset + scale * q
};

// The glTF primitive of `part` in the given storage; fills `placement` for quantised storage.
Json emitPrimitive(GlbBuilder& b, Part& part, FixtureStorage storage, int material, bool withTargetNormals,
                   Placement* placement) {
    Json prim;
    Json attributes;
    const bool skinned = !part.joints.empty();
    switch (storage) {
    case FixtureStorage::Plain:
    case FixtureStorage::Sparse:
        attributes["POSITION"] = b.addFloats(part.positions, "VEC3", true);
        attributes["NORMAL"] = b.addFloats(part.normals, "VEC3", false);
        attributes["TEXCOORD_0"] = b.addFloats(part.uvs, "VEC2", false);
        prim["indices"] = b.addIndices(part.indices);
        break;
    case FixtureStorage::Quantised: {
        glm::dvec3 lo(1e9), hi(-1e9);
        for (std::size_t i = 0; i < part.vertices(); ++i) {
            lo = glm::min(lo, at(part.positions, i));
            hi = glm::max(hi, at(part.positions, i));
        }
        placement->offset = 0.5 * (lo + hi);
        placement->scale = glm::max(0.5 * (hi - lo), glm::dvec3(0.02)); // deltas must fit too
        attributes["POSITION"] =
            quantisedShorts(b, part.positions, placement->offset, placement->scale, true);
        std::vector<std::int8_t> n;
        for (std::size_t i = 0; i < part.normals.size(); ++i) {
            n.push_back(static_cast<std::int8_t>(std::lround(part.normals[i] * 127.0f)));
            if (i % 3 == 2) n.push_back(0);
        }
        attributes["NORMAL"] = b.addAccessor(b.addView(n.data(), n.size(), kArrayBuffer, 4), kByte, "VEC3",
                                             part.vertices(), true);
        std::vector<std::uint16_t> uv;
        for (float v : part.uvs)
            uv.push_back(static_cast<std::uint16_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f)));
        attributes["TEXCOORD_0"] = b.addAccessor(b.addView(uv.data(), uv.size() * 2, kArrayBuffer),
                                                 kUnsignedShort, "VEC2", part.vertices(), true);
        prim["indices"] = b.addIndices(part.indices);
        break;
    }
    case FixtureStorage::Meshopt: {
        attributes["POSITION"] = meshoptFloats(b, part.positions, "VEC3", true, false);
        attributes["NORMAL"] = meshoptNormals(b, part.normals);
        attributes["TEXCOORD_0"] = meshoptFloats(b, part.uvs, "VEC2", false, false);
        std::vector<std::uint16_t> idx(part.indices.begin(), part.indices.end());
        const int view =
            b.addMeshoptView(idx.data(), idx.size(), 2, "TRIANGLES", "NONE", kElementArrayBuffer);
        prim["indices"] = b.addAccessor(view, kUnsignedShort, "SCALAR", idx.size(), false);
        break;
    }
    case FixtureStorage::Draco:
        throw std::logic_error("Draco primitives are emitted by emitDracoPrimitive");
    }
    if (skinned) {
        if (storage == FixtureStorage::Meshopt) {
            attributes["JOINTS_0"] = b.addAccessor(
                b.addMeshoptView(part.joints.data(), part.vertices(), 4, "ATTRIBUTES", "NONE", kArrayBuffer),
                kUnsignedByte, "VEC4", part.vertices(), false);
            attributes["WEIGHTS_0"] = meshoptFloats(b, part.weights, "VEC4", false, false);
        } else {
            attributes["JOINTS_0"] =
                b.addAccessor(b.addView(part.joints.data(), part.joints.size(), kArrayBuffer), kUnsignedByte,
                              "VEC4", part.vertices(), false);
            attributes["WEIGHTS_0"] = b.addFloats(part.weights, "VEC4", false);
        }
    }
    prim["attributes"] = attributes;
    prim["material"] = material;
    Json targets = Json::array();
    for (const auto& [name, delta] : part.targets) {
        Json t;
        switch (storage) {
        case FixtureStorage::Plain:
            t["POSITION"] = b.addFloats(delta, "VEC3", true);
            break;
        case FixtureStorage::Sparse:
            t["POSITION"] = b.addSparseVec3(delta, part.vertices() < 256 ? kUnsignedByte : kUnsignedShort);
            break;
        case FixtureStorage::Quantised:
            t["POSITION"] = quantisedShorts(b, delta, glm::dvec3(0.0), placement->scale, true);
            break;
        case FixtureStorage::Meshopt:
            t["POSITION"] = meshoptFloats(b, delta, "VEC3", true, true);
            break;
        case FixtureStorage::Draco:
            break;
        }
        if (withTargetNormals && storage == FixtureStorage::Plain) {
            std::vector<float> moved = part.positions;
            for (std::size_t i = 0; i < moved.size(); ++i) moved[i] += delta[i];
            std::vector<float> normals = computeNormals(moved, part.indices);
            for (std::size_t i = 0; i < normals.size(); ++i) normals[i] -= part.normals[i];
            t["NORMAL"] = b.addFloats(normals, "VEC3", false);
        }
        targets.push_back(t);
    }
    if (!targets.empty()) prim["targets"] = targets;
    return prim;
}

// The head primitive compressed with Draco (sequential encoding, attributes unquantised). The
// file's accessors and targets describe the decoded data, in decoded point order, as the
// extension asks of generators.
Json emitDracoPrimitive(GlbBuilder& b, Part& part, int material) {
    b.useExtension("KHR_draco_mesh_compression", true);
    const std::size_t n = part.vertices();
    draco::Mesh mesh;
    mesh.set_num_points(static_cast<std::uint32_t>(n));
    auto addAttribute = [&](draco::GeometryAttribute::Type type, int components, draco::DataType dataType,
                            const void* data, std::size_t elementBytes) {
        draco::GeometryAttribute ga;
        ga.Init(type, nullptr, static_cast<std::int8_t>(components), dataType, false,
                static_cast<std::int64_t>(elementBytes), 0);
        const int id = mesh.AddAttribute(ga, true, static_cast<std::uint32_t>(n));
        for (std::size_t i = 0; i < n; ++i)
            mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(static_cast<std::uint32_t>(i)),
                                                  static_cast<const unsigned char*>(data) + i * elementBytes);
        return id;
    };
    const int pos =
        addAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32, part.positions.data(), 12);
    const int nor =
        addAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32, part.normals.data(), 12);
    const int tex =
        addAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32, part.uvs.data(), 8);
    const int joi =
        addAttribute(draco::GeometryAttribute::GENERIC, 4, draco::DT_UINT8, part.joints.data(), 4);
    const int wei =
        addAttribute(draco::GeometryAttribute::GENERIC, 4, draco::DT_FLOAT32, part.weights.data(), 16);
    for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
        draco::Mesh::Face face;
        for (int c = 0; c < 3; ++c)
            face[c] = draco::PointIndex(part.indices[t + static_cast<std::size_t>(c)]);
        mesh.AddFace(face);
    }
    draco::Encoder encoder;
    encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
    draco::EncoderBuffer encoded;
    if (!encoder.EncodeMeshToBuffer(mesh, &encoded).ok()) throw std::runtime_error("Draco encoding failed");

    // Decode, and express everything in the decoded order.
    draco::DecoderBuffer in;
    in.Init(encoded.data(), encoded.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&in);
    if (!decoded.ok()) throw std::runtime_error("Draco decoding failed");
    const auto& d = *decoded.value();
    std::map<std::tuple<float, float, float, float, float>, std::size_t> original;
    for (std::size_t i = 0; i < n; ++i)
        original[{part.positions[3 * i], part.positions[3 * i + 1], part.positions[3 * i + 2],
                  part.uvs[2 * i], part.uvs[2 * i + 1]}] = i;
    Part out;
    const auto get = [&](int id, std::size_t point, int components) {
        std::vector<float> v(static_cast<std::size_t>(components));
        const auto* att = d.GetAttributeByUniqueId(mesh.attribute(id)->unique_id());
        att->ConvertValue<float>(att->mapped_index(draco::PointIndex(static_cast<std::uint32_t>(point))),
                                 static_cast<std::int8_t>(components), v.data());
        return v;
    };
    std::vector<std::size_t> from(d.num_points());
    for (std::size_t p = 0; p < d.num_points(); ++p) {
        const auto position = get(pos, p, 3), uv = get(tex, p, 2);
        from[p] = original.at({position[0], position[1], position[2], uv[0], uv[1]});
        out.positions.insert(out.positions.end(), position.begin(), position.end());
    }
    for (auto& [name, delta] : part.targets) {
        std::vector<float> reordered;
        for (std::size_t p = 0; p < from.size(); ++p)
            reordered.insert(reordered.end(), delta.begin() + static_cast<long>(3 * from[p]),
                             delta.begin() + static_cast<long>(3 * from[p] + 3));
        delta = reordered;
    }
    std::vector<std::uint32_t> indices;
    for (draco::FaceIndex f(0); f < d.num_faces(); ++f)
        for (int c = 0; c < 3; ++c) indices.push_back(d.face(f)[c].value());
    part.positions = out.positions;
    part.indices = indices;

    std::vector<double> lo, hi;
    vectorBounds(part.positions, 3, lo, hi);
    const std::size_t points = d.num_points();
    const int stream = b.addView(encoded.data(), encoded.size());
    Json attributes{{"POSITION", b.addAccessor(-1, kFloat, "VEC3", points, false, lo, hi)},
                    {"NORMAL", b.addAccessor(-1, kFloat, "VEC3", points, false)},
                    {"TEXCOORD_0", b.addAccessor(-1, kFloat, "VEC2", points, false)},
                    {"JOINTS_0", b.addAccessor(-1, kUnsignedByte, "VEC4", points, false)},
                    {"WEIGHTS_0", b.addAccessor(-1, kFloat, "VEC4", points, false)}};
    Json prim{{"attributes", attributes},
              {"indices", b.addAccessor(-1, points < 65535 ? kUnsignedShort : kUnsignedInt, "SCALAR",
                                        indices.size(), false)},
              {"material", material}};
    const auto uid = [&](int id) { return mesh.attribute(id)->unique_id(); };
    prim["extensions"] = {{"KHR_draco_mesh_compression",
                           {{"bufferView", stream},
                            {"attributes",
                             {{"POSITION", uid(pos)},
                              {"NORMAL", uid(nor)},
                              {"TEXCOORD_0", uid(tex)},
                              {"JOINTS_0", uid(joi)},
                              {"WEIGHTS_0", uid(wei)}}}}}};
    Json targets = Json::array();
    for (const auto& [name, delta] : part.targets)
        targets.push_back({{"POSITION", b.addFloats(delta, "VEC3", true)}});
    prim["targets"] = targets;
    return prim;
}

// A 2x2 RGBA PNG written byte by byte (stored zlib blocks), so the fixtures need no image library.
std::string tinyPng() {
    auto crc = [](const std::string& bytes) {
        std::uint32_t c = 0xFFFFFFFFu;
        for (unsigned char ch : bytes) {
            c ^= ch;
            for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
        }
        return c ^ 0xFFFFFFFFu;
    };
    auto be32 = [](std::uint32_t v) {
        return std::string{static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
                           static_cast<char>(v)};
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        return be32(static_cast<std::uint32_t>(data.size())) + type + data + be32(crc(type + data));
    };
    std::string raw;
    for (int y = 0; y < 2; ++y) {
        raw.push_back(0); // filter: none
        for (int x = 0; x < 2; ++x)
            raw += std::string{static_cast<char>(200), static_cast<char>(150 + 40 * x),
                               static_cast<char>(120 + 40 * y), static_cast<char>(255)};
    }
    std::uint32_t a = 1, b2 = 0;
    for (unsigned char ch : raw) {
        a = (a + ch) % 65521;
        b2 = (b2 + a) % 65521;
    }
    const auto len = static_cast<std::uint16_t>(raw.size());
    std::string zlib{static_cast<char>(0x78),
                     static_cast<char>(0x01),
                     static_cast<char>(1),
                     static_cast<char>(len & 0xFF),
                     static_cast<char>(len >> 8),
                     static_cast<char>(~len & 0xFF),
                     static_cast<char>((~len >> 8) & 0xFF)};
    zlib += raw + be32((b2 << 16) | a);
    const std::string header = be32(2) + be32(2) + std::string{8, 6, 0, 0, 0};
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", header) + chunk("IDAT", zlib) +
           chunk("IEND", "");
}

int addTexturedMaterial(GlbBuilder& b, const std::string& name) {
    b.useExtension("KHR_texture_transform", false);
    const std::string png = tinyPng();
    const int image = b.add("images", {{"name", name + "_baseColor"},
                                       {"bufferView", b.addView(png.data(), png.size())},
                                       {"mimeType", "image/png"}});
    const int sampler =
        b.add("samplers", {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 33648}});
    const int texture = b.add("textures", {{"sampler", sampler}, {"source", image}});
    return b.add(
        "materials",
        {{"name", name},
         {"pbrMetallicRoughness",
          {{"baseColorTexture",
            {{"index", texture}, {"extensions", {{"KHR_texture_transform", {{"scale", {1.0, 1.0}}}}}}}},
           {"metallicFactor", 0.0},
           {"roughnessFactor", 0.8}}},
         {"extras", {{"fixture", "skin"}}}});
}

Json meshObject(const std::string& name, const Part& part, Json primitive) {
    Json names = Json::array();
    for (const auto& t : part.targets) names.push_back(t.first);
    Json mesh{{"name", name}, {"primitives", Json::array({primitive})}};
    if (!part.targets.empty()) {
        mesh["weights"] = std::vector<double>(part.targets.size(), 0.0);
        mesh["extras"] = {{"targetNames", names}};
    }
    return mesh;
}

int addAnimation(GlbBuilder& b, const Skeleton& s, int headMeshNode, std::size_t headTargets,
                 bool byteWeights) {
    const std::vector<float> times{0.0f, 0.5f, 1.0f};
    const int input = b.addFloats(times, "SCALAR", true, 0);
    std::vector<float> rotations;
    for (float t : times) {
        const glm::quat q = glm::angleAxis(0.2f * t, glm::vec3(0, 0, 1));
        rotations.insert(rotations.end(), {q.x, q.y, q.z, q.w});
    }
    const int rotationOut = b.addFloats(rotations, "VEC4", false, 0);
    std::vector<float> weights;
    for (std::size_t k = 0; k < times.size(); ++k)
        for (std::size_t t = 0; t < headTargets; ++t)
            weights.push_back(k == 1 && (t == 1 || t == 12) ? 0.8f : 0.0f);
    int weightsOut = -1;
    if (byteWeights) {
        std::vector<std::uint8_t> bytes;
        for (float w : weights) bytes.push_back(static_cast<std::uint8_t>(std::lround(w * 255)));
        weightsOut = b.addAccessor(b.addView(bytes.data(), bytes.size()), 5121, "SCALAR", bytes.size(), true);
    } else {
        weightsOut = b.addFloats(weights, "SCALAR", false, 0);
    }
    return b.add("animations",
                 {{"name", "Talk"},
                  {"samplers",
                   {{{"input", input}, {"output", rotationOut}, {"interpolation", "LINEAR"}},
                    {{"input", input}, {"output", weightsOut}, {"interpolation", "LINEAR"}}}},
                  {"channels",
                   {{{"sampler", 0}, {"target", {{"node", s.neck}, {"path", "rotation"}}}},
                    {{"sampler", 1}, {"target", {{"node", headMeshNode}, {"path", "weights"}}}}}}});
}

} // namespace

std::vector<std::string> rpmVisemeNames() {
    return {"viseme_sil", "viseme_PP", "viseme_FF", "viseme_TH", "viseme_DD",
            "viseme_kk",  "viseme_CH", "viseme_SS", "viseme_nn", "viseme_RR",
            "viseme_aa",  "viseme_E",  "viseme_I",  "viseme_O",  "viseme_U"};
}

std::vector<std::string> rpmHeadTargetNames() {
    std::vector<std::string> names{"browInnerUp", "jawOpen"};
    for (const auto& v : rpmVisemeNames()) names.push_back(v);
    for (const char* n : {"mouthSmileLeft", "mouthSmileRight", "eyeBlinkLeft", "eyeBlinkRight"})
        names.push_back(n);
    return names;
}

std::string rpmLikeAvatar(const AvatarFixtureOptions& o) {
    GlbBuilder b;
    b.json["asset"]["extras"] = {{"fixture", "rpm-like"}};
    const bool skinned = o.storage != FixtureStorage::Quantised;
    if (o.storage == FixtureStorage::Quantised || o.storage == FixtureStorage::Meshopt)
        b.useExtension("KHR_mesh_quantization", true);
    Part head = headPart(o), teeth = teethPart(o), eye = eyePart(o), body = bodyPart();

    const int skinMaterial = addTexturedMaterial(b, "Wolf3D_Skin");
    b.useExtension("KHR_materials_emissive_strength", false);
    const int teethMaterial = b.add(
        "materials", {{"name", "Wolf3D_Teeth"},
                      {"emissiveFactor", {1.0, 1.0, 1.0}},
                      {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 0.2}}}}}});
    const int eyeMaterial =
        b.add("materials", {{"name", "Wolf3D_Eye"},
                            {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.3, 0.5, 1.0}}}}});
    const int bodyMaterial = b.add("materials", {{"name", "Wolf3D_Body"}});

    const int scene =
        b.add("scenes", {{"name", "Scene"}, {"nodes", Json::array()}, {"extras", {{"fixture", true}}}});
    b.json["scene"] = scene;
    auto addRoot = [&](Json node) {
        const int index = b.add("nodes", node);
        b.json["scenes"][static_cast<std::size_t>(scene)]["nodes"].push_back(index);
        return index;
    };

    Skeleton skeleton;
    int skin = -1;
    if (skinned) {
        skeleton = addSkeleton(b);
        b.json["scenes"][static_cast<std::size_t>(scene)]["nodes"].push_back(skeleton.armature);
        std::vector<float> ibm;
        for (const glm::dmat4& m : skeleton.bindWorld) {
            const glm::dmat4 inverse = glm::inverse(m);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) ibm.push_back(static_cast<float>(inverse[c][r]));
        }
        skin = b.add("skins", {{"name", "Wolf3D_Skeleton"},
                               {"joints", skeleton.jointNodes},
                               {"inverseBindMatrices", b.addFloats(ibm, "MAT4", false, 0)}});
        setSkinWeights(head, 3, 2, kMouth.y - 0.02);
        setSkinWeights(teeth, 3, 2, kMouth.y - 0.02);
        setSkinWeights(body, 1, 0, 1.1);
    }

    // Meshes in RPM's order: body, eyes, head, teeth.
    Placement placement;
    const auto emit = [&](Part& part, int material, bool normals) {
        if (o.storage == FixtureStorage::Draco && &part == &head)
            return emitDracoPrimitive(b, part, material);
        const FixtureStorage storage = o.storage == FixtureStorage::Draco ? FixtureStorage::Plain : o.storage;
        return emitPrimitive(b, part, storage, material, normals, &placement);
    };
    const int bodyMesh = b.add("meshes", meshObject("Wolf3D_Body", body, emit(body, bodyMaterial, false)));
    const Placement bodyPlacement = placement;
    const int eyeMeshes[2] = {b.add("meshes", meshObject("EyeLeft", eye, emit(eye, eyeMaterial, false))),
                              b.add("meshes", meshObject("EyeRight", eye, emit(eye, eyeMaterial, false)))};
    const Placement eyePlacement = placement;
    const int headMesh = b.add("meshes", meshObject("Wolf3D_Head", head, emit(head, skinMaterial, true)));
    const Placement headPlacement = placement;
    const int teethMesh =
        b.add("meshes", meshObject("Wolf3D_Teeth", teeth, emit(teeth, teethMaterial, false)));
    const Placement teethPlacement = placement;
    b.json["meshes"][static_cast<std::size_t>(headMesh)]["extras"]["fixture"] = "head";

    auto meshNode = [&](const std::string& name, int mesh, const Placement& p) {
        Json node{{"name", name}, {"mesh", mesh}};
        if (skinned) {
            node["skin"] = skin;
        } else {
            node["translation"] = {p.offset.x, p.offset.y, p.offset.z};
            node["scale"] = {p.scale.x, p.scale.y, p.scale.z};
        }
        return addRoot(node);
    };
    meshNode("Wolf3D_Body", bodyMesh, bodyPlacement);
    const int headNode = meshNode("Wolf3D_Head", headMesh, headPlacement);
    meshNode("Wolf3D_Teeth", teethMesh, teethPlacement);
    b.json["nodes"][static_cast<std::size_t>(headNode)]["extras"] = {{"fixture", "head node"}};
    for (int e = 0; e < 2; ++e) {
        const char* name = e == 0 ? "EyeLeft" : "EyeRight";
        if (skinned) {
            // Under the Head joint, placed by a matrix: the joint's stored frame includes the
            // armature's rotation and 0.01 scale, so the matrix scales by 100.
            const glm::dmat4 local =
                glm::inverse(storedHeadWorld(skeleton)) * glm::translate(glm::dmat4(1.0), kEyeCentres[e]);
            std::vector<double> matrix(glm::value_ptr(local), glm::value_ptr(local) + 16);
            const int node = b.add("nodes", {{"name", name}, {"mesh", eyeMeshes[e]}, {"matrix", matrix}});
            b.json["nodes"][static_cast<std::size_t>(skeleton.head)]["children"].push_back(node);
        } else {
            const glm::dvec3 t = kEyeCentres[e] + eyePlacement.offset;
            addRoot({{"name", name},
                     {"mesh", eyeMeshes[e]},
                     {"translation", {t.x, t.y, t.z}},
                     {"scale", {eyePlacement.scale.x, eyePlacement.scale.y, eyePlacement.scale.z}}});
        }
    }
    if (o.animation && skinned) addAnimation(b, skeleton, headNode, head.targets.size(), o.byteWeights);
    return b.glb();
}

std::vector<std::string> vroidFaceTargetNames() {
    return {"Fcl_ALL_Neutral", "Fcl_ALL_Angry", "Fcl_ALL_Joy", "Fcl_EYE_Close", "Fcl_MTH_A",
            "Fcl_MTH_I",       "Fcl_MTH_U",     "Fcl_MTH_E",   "Fcl_MTH_O",     "Fcl_MTH_Close"};
}

std::string vroidLikeAvatar(bool vrm1) {
    GlbBuilder b;
    AvatarFixtureOptions o;
    o.headColumns = 20;
    o.headRows = 12;
    Part face = headPart(o);
    Part mouth = teethPart(o);
    // VRoid's mouth shapes: vowels as mixes of the mouth motions; expressions elsewhere.
    const Mix vowels[5] = {
        {1.0, 0, 0.2, 0}, {0.4, 0, 0.7, 0}, {0.3, 1.0, 0, 0}, {0.6, 0, 0.6, 0}, {0.7, 0.8, 0, 0}};
    const auto faceTargets = [&](Part& part, bool isFace) {
        part.targets.clear();
        for (const std::string& name : vroidFaceTargetNames()) {
            Mix m{0, 0, 0, 0};
            if (name.rfind("Fcl_MTH_", 0) == 0 && name != "Fcl_MTH_Close")
                m = vowels[std::string("AIUEO").find(name.back())];
            if (name == "Fcl_MTH_Close") m = {0, 0, 0, 1.0};
            if (name == "Fcl_ALL_Joy") m = {0.2, 0, 0.5, 0};
            part.targets.emplace_back(name, field(part, [&](const glm::dvec3& p) {
                                          if (!isFace)
                                              return p.y < kMouth.y - 0.003
                                                         ? glm::dvec3(0, -0.014 * m.open, 0)
                                                         : glm::dvec3(0.0);
                                          glm::dvec3 d = mouthMotion(p, m);
                                          if (name == "Fcl_EYE_Close" && p.y > kEyeCentres[0].y - 0.01 &&
                                              p.y < kEyeCentres[0].y + 0.02)
                                              d += glm::dvec3(0, -0.004, 0);
                                          if (name == "Fcl_ALL_Angry" && p.y > kEyeCentres[0].y)
                                              d += glm::dvec3(0, -0.002, 0.001);
                                          return d;
                                      }));
        }
    };
    faceTargets(face, true);
    faceTargets(mouth, false);
    const int skinMaterial = addTexturedMaterial(b, "N00_000_00_Face_00_SKIN");
    const int mouthMaterial = b.add("materials", {{"name", "N00_000_00_FaceMouth_00_FACE"}});
    Json names = Json::array();
    for (const auto& t : face.targets) names.push_back(t.first);
    Json p0 = emitPrimitive(b, face, FixtureStorage::Plain, skinMaterial, false, nullptr);
    Json p1 = emitPrimitive(b, mouth, FixtureStorage::Plain, mouthMaterial, false, nullptr);
    p0["extras"] = {{"targetNames", names}};
    p1["extras"] = {{"targetNames", names}};
    const int faceMesh = b.add("meshes", {{"name", "Face.baked"}, {"primitives", {p0, p1}}});
    Part body = bodyPart();
    const int bodyMesh = b.add(
        "meshes",
        {{"name", "Body.baked"},
         {"primitives", {emitPrimitive(b, body, FixtureStorage::Plain, skinMaterial, false, nullptr)}}});
    const int root = b.add("nodes", {{"name", "Root"}, {"children", Json::array()}});
    const int faceNode = b.add("nodes", {{"name", "Face"}, {"mesh", faceMesh}});
    const int bodyNode = b.add("nodes", {{"name", "Body"}, {"mesh", bodyMesh}});
    b.json["nodes"][static_cast<std::size_t>(root)]["children"] = {faceNode, bodyNode};
    b.json["scenes"] = {{{"nodes", {root}}}};
    b.json["scene"] = 0;
    const auto index = [&](const std::string& n) {
        const auto all = vroidFaceTargetNames();
        return static_cast<int>(std::find(all.begin(), all.end(), n) - all.begin());
    };
    if (!vrm1) {
        b.useExtension("VRM", false);
        Json groups = Json::array();
        for (const char* preset : {"a", "i", "u", "e", "o"}) {
            const std::string target = std::string("Fcl_MTH_") + static_cast<char>(std::toupper(preset[0]));
            groups.push_back({{"name", std::string(1, static_cast<char>(std::toupper(preset[0])))},
                              {"presetName", preset},
                              {"binds", {{{"mesh", faceMesh}, {"index", index(target)}, {"weight", 100}}}},
                              {"materialValues", Json::array()}});
        }
        groups.push_back({{"name", "Joy"},
                          {"presetName", "joy"},
                          {"binds", {{{"mesh", faceMesh}, {"index", index("Fcl_ALL_Joy")}, {"weight", 100}}}},
                          {"materialValues", Json::array()}});
        b.json["extensions"]["VRM"] = {{"exporterVersion", "VisemeLab fixture"},
                                       {"specVersion", "0.0"},
                                       {"meta", {{"title", "fixture"}, {"version", "1"}}},
                                       {"blendShapeMaster", {{"blendShapeGroups", groups}}}};
    } else {
        b.useExtension("VRMC_vrm", false);
        Json preset;
        const std::pair<const char*, const char*> vowels1[] = {
            {"aa", "A"}, {"ih", "I"}, {"ou", "U"}, {"ee", "E"}, {"oh", "O"}};
        for (const auto& [name, vowel] : vowels1)
            preset[name] = {
                {"morphTargetBinds",
                 {{{"node", faceNode}, {"index", index(std::string("Fcl_MTH_") + vowel)}, {"weight", 1.0}}}}};
        preset["happy"] = {
            {"morphTargetBinds", {{{"node", faceNode}, {"index", index("Fcl_ALL_Joy")}, {"weight", 1.0}}}}};
        b.json["extensions"]["VRMC_vrm"] = {
            {"specVersion", "1.0"}, {"meta", {{"name", "fixture"}}}, {"expressions", {{"preset", preset}}}};
    }
    return b.glb();
}

} // namespace vl::test
