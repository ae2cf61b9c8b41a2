#include "core/gltf/TargetStorage.h"

#include "core/gltf/BufferViews.h"
#include "core/gltf/GlbRepack.h"
#include "core/gltf/GltfDocument.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <tuple>

namespace vl {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kFloat = 5126, kByte = 5120, kShort = 5122;
constexpr int kArrayBuffer = 34962;

std::size_t align4(std::size_t n) {
    return (n + 3) / 4 * 4;
}

// Lexicographic precision rank: float over integer, then mantissa bits or integer step, then compression.
std::tuple<int, int, int> rank(const TargetStorage& s) {
    if (s.componentType == kFloat)
        return {2, s.filter == MeshoptFilter::Exponential ? s.exponentBits : 25, s.meshopt};
    const bool isShort = s.componentType == kShort;
    const int step = s.normalized ? (isShort ? 4 : 3) : (isShort ? 2 : 1);
    return {1, step, s.meshopt};
}

std::string describe(const TargetStorage& s) {
    if (s.componentType == kFloat) return "float32";
    return std::string(s.componentType == kShort ? "SHORT" : "BYTE") + (s.normalized ? " normalised" : "");
}

// The values as stored: floats, or integers on the member grid (round, clamp).
struct Stored {
    std::vector<float> floats;      // float storage
    std::vector<std::int32_t> ints; // integer storage
    bool isZero(std::size_t i) const { return floats.empty() ? ints[i] == 0 : floats[i] == 0.0f; }
};

Stored quantise(const std::vector<double>& values, const TargetStorage& s) {
    Stored out;
    if (s.componentType == kFloat) {
        out.floats.assign(values.begin(), values.end());
        return out;
    }
    const bool isShort = s.componentType == kShort;
    const double top = isShort ? 32767.0 : 127.0;
    // Normalised: -1 is the lowest value (the spec's max(c / top, -1)), so -top suffices.
    const double bottom = s.normalized ? -top : -(top + 1.0);
    const double scale = s.normalized ? top : 1.0;
    out.ints.reserve(values.size());
    for (double v : values)
        out.ints.push_back(static_cast<std::int32_t>(std::clamp(std::round(v * scale), bottom, top)));
    return out;
}

void putComponent(char* at, const Stored& v, std::size_t i, int componentType) {
    if (componentType == kFloat) {
        std::memcpy(at, &v.floats[i], 4);
    } else if (componentType == kShort) {
        const auto s = static_cast<std::int16_t>(v.ints[i]);
        std::memcpy(at, &s, 2);
    } else {
        *at = static_cast<char>(static_cast<std::int8_t>(v.ints[i]));
    }
}

// count elements of 3 components at `stride` bytes (padding zero).
std::string packed(const Stored& v, int componentType, std::size_t count, std::size_t stride) {
    const std::size_t size = componentType == kFloat ? 4 : componentType == kShort ? 2 : 1;
    std::string bytes(count * stride, '\0');
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < 3; ++c)
            putComponent(bytes.data() + i * stride + c * size, v, 3 * i + c, componentType);
    return bytes;
}

std::string encodeVertices(const std::string& bytes, std::size_t count, std::size_t stride) {
    meshopt_encodeVertexVersion(0); // EXT_meshopt_compression: version 0 only
    std::string out(meshopt_encodeVertexBufferBound(count, stride), '\0');
    out.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(out.data()), out.size(),
                                          bytes.data(), count, stride));
    return out;
}

// Min/max per component of what readers get: integers as stored, floats as decoded.
void addBounds(Json& accessor, const std::vector<double>& stored) {
    std::vector<double> lo(3, std::numeric_limits<double>::infinity()),
        hi(3, -std::numeric_limits<double>::infinity());
    for (std::size_t i = 0; i < stored.size(); ++i) {
        lo[i % 3] = std::min(lo[i % 3], stored[i]);
        hi[i % 3] = std::max(hi[i % 3], stored[i]);
    }
    if (stored.empty()) lo = hi = {0.0, 0.0, 0.0};
    accessor["min"] = lo;
    accessor["max"] = hi;
}

std::vector<double> asDoubles(const Stored& v) {
    return v.floats.empty() ? std::vector<double>(v.ints.begin(), v.ints.end())
                            : std::vector<double>(v.floats.begin(), v.floats.end());
}

} // namespace

TargetStorage storageOf(const GltfDocument& doc, BufferViews& views, int accessor, const std::string& where) {
    if (accessor < 0 || static_cast<std::size_t>(accessor) >= doc.model.accessors.size())
        doc.fail(where, "accessor " + std::to_string(accessor) + " does not exist");
    const tinygltf::Accessor& a = doc.model.accessors[static_cast<std::size_t>(accessor)];
    TargetStorage s;
    if (a.componentType == kByte || a.componentType == kShort) {
        s.componentType = a.componentType;
        s.normalized = a.normalized;
    }
    if (a.bufferView < 0 || !views.isCompressed(a.bufferView)) return s;
    s.meshopt = true;
    const Json& ext = doc.json["bufferViews"][static_cast<std::size_t>(a.bufferView)]["extensions"]
                              ["EXT_meshopt_compression"];
    if (ext.value("filter", std::string("NONE")) != "EXPONENTIAL" || s.componentType != kFloat) return s;
    s.filter = MeshoptFilter::Exponential;
    const ViewBytes bytes = views.view(a.bufferView, where);
    const std::size_t stride = ext.value("byteStride", std::size_t{0});
    s.exponentBits = stride > 0 && stride % 4 == 0
                         ? inferExponentBits(bytes.data, bytes.size / stride, stride)
                         : kDefaultExponentBits;
    return s;
}

TargetStorage morePrecise(const TargetStorage& a, const TargetStorage& b) {
    return rank(b) > rank(a) ? b : a;
}

int inferExponentBits(const unsigned char* data, std::size_t count, std::size_t stride) {
    const std::size_t size = count * stride;
    std::vector<float> input(size / 4);
    std::memcpy(input.data(), data, size);
    std::vector<unsigned char> trial(size);
    const auto roundTrips = [&](int bits) {
        meshopt_encodeFilterExp(trial.data(), count, stride, bits, input.data());
        meshopt_decodeFilterExp(trial.data(), count, stride);
        return std::memcmp(trial.data(), data, size) == 0;
    };
    // Data that round-trips with K bits does with K + 1 (a finer grid with the same exponent
    // choice): bisect instead of trying all 24 on a million vertices.
    if (!roundTrips(24)) return kDefaultExponentBits;
    int lo = 1, hi = 24; // hi round-trips
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (roundTrips(mid))
            hi = mid;
        else
            lo = mid + 1;
    }
    return hi;
}

int addVec3Target(GlbRepack& out, const std::vector<double>& values, const TargetStorage& storage,
                  bool bounds, StorageTally* tally) {
    const std::size_t count = values.size() / 3;
    const Stored stored = quantise(values, storage);
    std::vector<std::uint32_t> nonZero;
    for (std::size_t i = 0; i < count; ++i)
        if (!stored.isZero(3 * i) || !stored.isZero(3 * i + 1) || !stored.isZero(3 * i + 2))
            nonZero.push_back(static_cast<std::uint32_t>(i));

    Json accessor{{"componentType", storage.componentType}, {"count", count}, {"type", "VEC3"}};
    if (storage.normalized) accessor["normalized"] = true;
    const auto count1 = [&](const std::string& layout) {
        if (tally) ++(*tally)[describe(storage) + ", " + layout];
    };
    if (nonZero.empty()) { // zeros need no bytes, in any type: a float accessor needs no extension
        Json zero{{"componentType", kFloat}, {"count", count}, {"type", "VEC3"}};
        if (bounds) addBounds(zero, {});
        if (tally) ++(*tally)["no bytes (all zero)"];
        return out.addAccessor(zero);
    }
    if (storage.componentType != kFloat) out.requireExtension("KHR_mesh_quantization");

    // The candidates' bytes, then the smallest.
    const std::size_t componentSize = storage.componentType == kFloat   ? 4
                                      : storage.componentType == kShort ? 2
                                                                        : 1;
    const std::size_t element = 3 * componentSize, stride = align4(element);
    const std::size_t indexBytes = count <= 0x100 ? 1 : count <= 0x10000 ? 2 : 4;
    const std::size_t sparseSize = align4(nonZero.size() * indexBytes) + nonZero.size() * element;
    const std::size_t denseSize = count * stride;
    std::string encoded, filtered;
    std::vector<float> decoded; // EXPONENTIAL: the floats readers get
    if (storage.meshopt) {
        if (storage.filter == MeshoptFilter::Exponential) {
            filtered.assign(count * 12, '\0');
            meshopt_encodeFilterExp(filtered.data(), count, 12, storage.exponentBits, stored.floats.data());
            decoded.resize(3 * count);
            std::memcpy(decoded.data(), filtered.data(), filtered.size());
            meshopt_decodeFilterExp(decoded.data(), count, 12);
        }
        encoded =
            encodeVertices(filtered.empty() ? packed(stored, storage.componentType, count, stride) : filtered,
                           count, stride);
    }
    const bool compressedSmallest =
        storage.meshopt && !encoded.empty() && encoded.size() < std::min(sparseSize, denseSize);

    if (compressedSmallest) {
        if (bounds) {
            Stored exact = stored;
            if (!decoded.empty()) exact.floats = decoded;
            addBounds(accessor, asDoubles(exact));
        }
        const bool exponential = storage.filter == MeshoptFilter::Exponential;
        accessor["bufferView"] = out.addMeshoptView(std::move(encoded), count, stride, "ATTRIBUTES",
                                                    exponential ? "EXPONENTIAL" : "NONE", kArrayBuffer);
        count1(
            "dense, EXT_meshopt_compression" +
            (exponential ? " EXPONENTIAL " + std::to_string(storage.exponentBits) + " bits" : std::string()));
        return out.addAccessor(accessor);
    }
    if (bounds) addBounds(accessor, asDoubles(stored));
    if (sparseSize < denseSize) {
        std::string indices, sparseValues;
        for (std::uint32_t i : nonZero) {
            indices.append(reinterpret_cast<const char*>(&i), indexBytes); // little-endian low bytes
            std::string one(element, '\0');
            for (std::size_t c = 0; c < 3; ++c)
                putComponent(one.data() + c * componentSize, stored, 3 * i + c, storage.componentType);
            sparseValues += one; // tightly packed: sparse views have no byteStride
        }
        const int indexType = indexBytes == 1 ? 5121 : indexBytes == 2 ? 5123 : 5125;
        accessor["sparse"] = {
            {"count", nonZero.size()},
            {"indices", {{"bufferView", out.addView(std::move(indices))}, {"componentType", indexType}}},
            {"values", {{"bufferView", out.addView(std::move(sparseValues))}}}};
        count1("sparse");
        return out.addAccessor(accessor);
    }
    accessor["bufferView"] = out.addView(packed(stored, storage.componentType, count, stride), kArrayBuffer,
                                         stride == element ? 0 : stride);
    count1("dense");
    return out.addAccessor(accessor);
}

} // namespace vl
