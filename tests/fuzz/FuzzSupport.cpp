#include "FuzzSupport.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

namespace vl::fuzz {

void fail(std::string_view what) {
    std::fprintf(stderr, "fuzz target: %.*s\n", static_cast<int>(what.size()), what.data());
    std::abort();
}

void checkMesh(const MeshData& mesh) {
    if (mesh.positions.empty() || mesh.triangles.empty()) fail("loaded a mesh without vertices or triangles");
    if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size())
        fail("(u,v) count differs from vertices");
    for (const Vec3& p : mesh.positions)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) fail("non-finite position");
    for (const Vec2& uv : mesh.uvs)
        if (!std::isfinite(uv[0]) || !std::isfinite(uv[1])) fail("non-finite (u,v)");
    for (const Triangle& t : mesh.triangles)
        for (const std::uint32_t v : t)
            if (v >= mesh.positions.size()) fail("triangle index out of range");
}

namespace {

struct PrivateFolder {
    std::filesystem::path path;
    PrivateFolder()
        : path(std::filesystem::temp_directory_path() / ("visemelab-fuzz-" + std::to_string(::getpid()))) {}
    ~PrivateFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

} // namespace

std::filesystem::path freshInputFolder() {
    static const PrivateFolder folder;
    std::filesystem::remove_all(folder.path);
    std::filesystem::create_directories(folder.path);
    return folder.path;
}

void writeFile(const std::filesystem::path& file, std::string_view bytes) {
    std::ofstream out(file, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out.flush()) fail("cannot write the fuzz input file " + file.string());
}

std::filesystem::path writeInputFile(std::string_view name, const std::uint8_t* data, std::size_t size) {
    const std::filesystem::path file = freshInputFolder() / name;
    writeFile(file, asText(data, size));
    return file;
}

bool looksLikeJson(std::string_view text) {
    for (const char c : text) {
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') continue;
        return c == '{' || c == '[';
    }
    return false;
}

} // namespace vl::fuzz
