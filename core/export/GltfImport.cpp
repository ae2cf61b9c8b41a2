#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/export/Gltf.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

namespace vl {
namespace {

// Reads accessors into doubles with every offset checked against its buffer, so a malformed file
// produces an error naming the accessor instead of a read out of bounds.
class AccessorReader {
  public:
    AccessorReader(const tinygltf::Model& model, std::string_view source) : model_(model), source_(source) {}

    [[noreturn]] void fail(const std::string& element, const std::string& what) const {
        throwInputError(std::string(source_) + ": " + element, what);
    }

    // Flattened components (count * components), normalised integers mapped to [0,1] / [-1,1].
    std::vector<double> read(int index, int expectedType, const std::string& element) const {
        if (index < 0 || index >= static_cast<int>(model_.accessors.size()))
            fail(element, "accessor " + std::to_string(index) + " does not exist");
        const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(index)];
        const std::string where = element + " (accessor " + std::to_string(index) + ")";
        if (expectedType >= 0 && a.type != expectedType) fail(where, "unexpected accessor type");
        const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
        const int componentSize =
            tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
        if (components <= 0 || componentSize <= 0) fail(where, "unsupported type or component type");
        if (a.count > kMaxElements) fail(where, "more than " + std::to_string(kMaxElements) + " elements");
        std::vector<double> out(a.count * static_cast<std::size_t>(components), 0.0);
        if (a.bufferView >= 0)
            readDense(a.bufferView, a.byteOffset, a.count, components, a.componentType, a.normalized,
                      out.data(), where);
        if (a.sparse.isSparse) readSparse(a, components, out, where);
        for (double v : out)
            if (!std::isfinite(v)) fail(where, "non-finite value");
        return out;
    }

  private:
    static constexpr std::size_t kMaxElements = std::size_t{1} << 28;

    const std::vector<unsigned char>& viewBytes(int viewIndex, std::size_t& begin, std::size_t& length,
                                                std::size_t& stride, const std::string& where) const {
        if (viewIndex < 0 || viewIndex >= static_cast<int>(model_.bufferViews.size()))
            fail(where, "buffer view " + std::to_string(viewIndex) + " does not exist");
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(viewIndex)];
        if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size()))
            fail(where, "buffer " + std::to_string(view.buffer) + " does not exist");
        const std::vector<unsigned char>& data = model_.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            fail(where, "buffer view " + std::to_string(viewIndex) + " lies outside its buffer");
        begin = view.byteOffset;
        length = view.byteLength;
        stride = view.byteStride;
        return data;
    }

    static double component(const unsigned char* p, int componentType, bool normalized) {
        switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float f;
            std::memcpy(&f, p, 4);
            return f;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return normalized ? p[0] / 255.0 : p[0];
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const auto v = static_cast<signed char>(p[0]);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default:
            return std::nan("");
        }
    }

    void readDense(int viewIndex, std::size_t byteOffset, std::size_t count, int components,
                   int componentType, bool normalized, double* out, const std::string& where) const {
        if (count == 0) return;
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(componentType));
        if (size <= 0) fail(where, "unsupported component type");
        const std::size_t elementSize = static_cast<std::size_t>(components * size);
        std::size_t begin, length, stride;
        const std::vector<unsigned char>& data = viewBytes(viewIndex, begin, length, stride, where);
        if (stride == 0) stride = elementSize;
        if (stride < elementSize) fail(where, "byte stride smaller than an element");
        // Needs byteOffset + (count - 1) * stride + elementSize <= length, checked without overflow.
        if (byteOffset > length || length - byteOffset < elementSize ||
            count - 1 > (length - byteOffset - elementSize) / stride)
            fail(where, "accessor runs past its buffer view");
        for (std::size_t i = 0; i < count; ++i) {
            const unsigned char* element = data.data() + begin + byteOffset + i * stride;
            for (int c = 0; c < components; ++c)
                out[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
                    component(element + c * size, componentType, normalized);
        }
    }

    void readSparse(const tinygltf::Accessor& a, int components, std::vector<double>& out,
                    const std::string& where) const {
        const auto count = static_cast<std::size_t>(a.sparse.count);
        if (a.sparse.count < 0 || count > a.count) fail(where, "invalid sparse count");
        std::vector<double> indices(count);
        const int indexType = a.sparse.indices.componentType;
        readDense(a.sparse.indices.bufferView, static_cast<std::size_t>(a.sparse.indices.byteOffset), count,
                  1, indexType, false, indices.data(), where + " sparse indices");
        std::vector<double> values(count * static_cast<std::size_t>(components));
        readDense(a.sparse.values.bufferView, static_cast<std::size_t>(a.sparse.values.byteOffset), count,
                  components, a.componentType, a.normalized, values.data(), where + " sparse values");
        for (std::size_t i = 0; i < count; ++i) {
            if (indices[i] >= static_cast<double>(a.count)) fail(where, "sparse index out of range");
            const auto target = static_cast<std::size_t>(indices[i]);
            for (int c = 0; c < components; ++c)
                out[target * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)] =
                    values[i * static_cast<std::size_t>(components) + static_cast<std::size_t>(c)];
        }
    }

    const tinygltf::Model& model_;
    std::string_view source_;
};

int attribute(const tinygltf::Primitive& p, const char* name) {
    const auto it = p.attributes.find(name);
    return it == p.attributes.end() ? -1 : it->second;
}
int attribute(const std::map<std::string, int>& attributes, const char* name) {
    const auto it = attributes.find(name);
    return it == attributes.end() ? -1 : it->second;
}

std::vector<Vec3> toVec3(const std::vector<double>& xyz) {
    std::vector<Vec3> out(xyz.size() / 3);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    return out;
}

// Restores names, members, frequencies and the phoneme map from VisemeLab's mesh.extras.
void readExtras(const tinygltf::Value& extras, ReducedModel& model, std::string_view source) {
    const std::string where = std::string(source) + ": mesh.extras";
    const std::size_t keyCount = model.keys.size();
    if (extras.Has("targetNames") && extras.Get("targetNames").IsArray()) {
        const tinygltf::Value& names = extras.Get("targetNames");
        if (names.ArrayLen() != keyCount)
            throwInputError(where + ".targetNames", "count differs from the morph targets");
        for (std::size_t k = 0; k < keyCount; ++k) {
            if (!names.Get(static_cast<int>(k)).IsString())
                throwInputError(where + ".targetNames/" + std::to_string(k), "not a string");
            model.keys[k].name = names.Get(static_cast<int>(k)).Get<std::string>();
        }
    }
    if (extras.Has("targetFrequencies") && extras.Get("targetFrequencies").ArrayLen() == keyCount)
        for (std::size_t k = 0; k < keyCount; ++k) {
            const tinygltf::Value& f = extras.Get("targetFrequencies").Get(static_cast<int>(k));
            if (f.IsNumber()) model.keys[k].frequency = f.GetNumberAsDouble();
        }
    if (extras.Has("targetMembers") && extras.Get("targetMembers").ArrayLen() == keyCount)
        for (std::size_t k = 0; k < keyCount; ++k) {
            const tinygltf::Value& members = extras.Get("targetMembers").Get(static_cast<int>(k));
            model.keys[k].members.clear();
            for (std::size_t i = 0; i < members.ArrayLen(); ++i)
                if (members.Get(static_cast<int>(i)).IsString())
                    model.keys[k].members.push_back(members.Get(static_cast<int>(i)).Get<std::string>());
        }
    if (extras.Has("phonemeToTarget") && extras.Get("phonemeToTarget").IsObject()) {
        const tinygltf::Value& map = extras.Get("phonemeToTarget");
        for (const std::string& phoneme : map.Keys()) {
            const tinygltf::Value& v = map.Get(phoneme);
            const double k = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
            if (!(k >= 0 && k < static_cast<double>(keyCount)) || k != std::floor(k))
                throwInputError(where + ".phonemeToTarget/" + phoneme, "not a morph target index");
            model.phonemeToKey.emplace_back(phoneme, static_cast<int>(k));
        }
    }
    if (extras.Has("phonemeFrequencies") && extras.Get("phonemeFrequencies").IsObject()) {
        const tinygltf::Value& map = extras.Get("phonemeFrequencies");
        for (const std::string& phoneme : map.Keys())
            if (map.Get(phoneme).IsNumber())
                model.phonemeFrequencies.emplace_back(phoneme, map.Get(phoneme).GetNumberAsDouble());
    }
}

bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
               void*) {
    return true; // textures are not part of a face shape set
}

} // namespace

ReducedModel parseGltf(std::string_view bytes, std::string_view source, bool binary,
                       const std::filesystem::path& baseDir) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    tinygltf::Model gltf;
    std::string error, warning;
    const bool ok =
        binary ? loader.LoadBinaryFromMemory(&gltf, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(bytes.data()),
                                             static_cast<unsigned int>(bytes.size()), baseDir.string())
               : loader.LoadASCIIFromString(&gltf, &error, &warning, bytes.data(),
                                            static_cast<unsigned int>(bytes.size()), baseDir.string());
    if (!ok) throwInputError(source, "not a readable glTF file: " + (error.empty() ? warning : error));
    if (gltf.meshes.empty()) throwInputError(source, "the glTF file has no mesh");

    std::size_t meshIndex = 0;
    for (std::size_t m = 0; m < gltf.meshes.size(); ++m)
        if (!gltf.meshes[m].primitives.empty() && !gltf.meshes[m].primitives[0].targets.empty()) {
            meshIndex = m;
            break;
        }
    const tinygltf::Mesh& mesh = gltf.meshes[meshIndex];
    const std::string meshWhere = "meshes/" + std::to_string(meshIndex);
    if (mesh.primitives.empty()) throwInputError(source, meshWhere + ": no primitives");
    const std::size_t targetCount = mesh.primitives[0].targets.size();

    AccessorReader reader(gltf, source);
    ReducedModel model;
    model.keys.resize(targetCount);
    bool anyUVs = false, allUVs = true;
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const tinygltf::Primitive& prim = mesh.primitives[p];
        const std::string where = meshWhere + "/primitives/" + std::to_string(p);
        if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1)
            reader.fail(where,
                        "only triangle primitives are supported (mode " + std::to_string(prim.mode) + ")");
        if (prim.targets.size() != targetCount)
            reader.fail(where, "has " + std::to_string(prim.targets.size()) +
                                   " morph targets, the first primitive " + std::to_string(targetCount));
        const int positionAccessor = attribute(prim, "POSITION");
        if (positionAccessor < 0) reader.fail(where, "no POSITION attribute");
        const std::vector<Vec3> positions =
            toVec3(reader.read(positionAccessor, TINYGLTF_TYPE_VEC3, where + "/POSITION"));
        const std::size_t base = model.neutral.positions.size();
        if (base + positions.size() > 0xFFFFFFFFu) reader.fail(where, "too many vertices");

        std::vector<double> indices;
        if (prim.indices >= 0) {
            indices = reader.read(prim.indices, TINYGLTF_TYPE_SCALAR, where + "/indices");
        } else {
            indices.resize(positions.size());
            for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<double>(i);
        }
        if (indices.size() % 3 != 0) reader.fail(where, "index count is not a multiple of 3");
        for (std::size_t i = 0; i < indices.size(); i += 3) {
            Triangle t;
            for (int c = 0; c < 3; ++c) {
                const double index = indices[i + static_cast<std::size_t>(c)];
                if (index < 0 || index >= static_cast<double>(positions.size()))
                    reader.fail(where,
                                "index " + std::to_string(static_cast<long long>(index)) + " out of range");
                t[static_cast<std::size_t>(c)] =
                    static_cast<std::uint32_t>(base + static_cast<std::size_t>(index));
            }
            model.neutral.triangles.push_back(t);
        }

        const int uvAccessor = attribute(prim, "TEXCOORD_0");
        if (uvAccessor >= 0) {
            const std::vector<double> uv = reader.read(uvAccessor, TINYGLTF_TYPE_VEC2, where + "/TEXCOORD_0");
            if (uv.size() != 2 * positions.size())
                reader.fail(where, "TEXCOORD_0 count differs from POSITION");
            model.neutral.uvs.resize(base);
            for (std::size_t i = 0; i < positions.size(); ++i)
                model.neutral.uvs.emplace_back(uv[2 * i], 1.0 - uv[2 * i + 1]);
            anyUVs = true;
        } else {
            allUVs = false;
        }
        model.neutral.positions.insert(model.neutral.positions.end(), positions.begin(), positions.end());

        for (std::size_t k = 0; k < targetCount; ++k) {
            const std::string targetWhere = where + "/targets/" + std::to_string(k);
            const int delta = attribute(prim.targets[k], "POSITION");
            std::vector<Vec3> shape = positions;
            if (delta >= 0) {
                const std::vector<Vec3> d =
                    toVec3(reader.read(delta, TINYGLTF_TYPE_VEC3, targetWhere + "/POSITION"));
                if (d.size() != positions.size())
                    reader.fail(targetWhere, "POSITION count differs from the primitive");
                for (std::size_t i = 0; i < d.size(); ++i) shape[i] += d[i];
            }
            auto& keyPositions = model.keys[k].positions;
            keyPositions.insert(keyPositions.end(), shape.begin(), shape.end());
        }
    }
    if (anyUVs && !allUVs)
        throwInputError(source, meshWhere + ": some primitives have TEXCOORD_0 and some not");
    if (model.neutral.positions.empty() || model.neutral.triangles.empty())
        throwInputError(source, meshWhere + ": the mesh is empty");

    for (std::size_t k = 0; k < targetCount; ++k) model.keys[k].name = "target" + std::to_string(k);
    readExtras(mesh.extras, model, source);
    for (KeyMesh& key : model.keys)
        if (key.members.empty()) key.members.push_back(key.name);
    validateReducedModel(model, source);
    return model;
}

ReducedModel readGltf(const std::filesystem::path& path) {
    const std::string bytes = readFileToString(path);
    const bool binary = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
    return parseGltf(bytes, path.string(), binary, path.parent_path());
}

} // namespace vl
