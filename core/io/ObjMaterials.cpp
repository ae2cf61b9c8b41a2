#include "core/io/ObjMaterials.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/io/ImageDecode.h"
#include "core/io/MeshIO.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace vl {
namespace {

std::vector<std::string_view> tokens(std::string_view line) {
    line = line.substr(0, line.find('#'));
    std::vector<std::string_view> out;
    std::size_t pos = 0;
    while (true) {
        while (pos < line.size() && std::isspace(static_cast<unsigned char>(line[pos]))) ++pos;
        const std::size_t start = pos;
        while (pos < line.size() && !std::isspace(static_cast<unsigned char>(line[pos]))) ++pos;
        if (start == pos) return out;
        out.push_back(line.substr(start, pos - start));
    }
}

template <typename Visit> void forEachLine(std::string_view text, Visit&& visit) {
    std::size_t line = 0, pos = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        visit(++line, text.substr(pos, end - pos));
        pos = end + 1;
    }
}

std::optional<float> number(std::string_view token) {
    std::istringstream in{std::string(token)};
    float value = 0;
    if (!(in >> value) || !in.eof() || !std::isfinite(value)) return std::nullopt;
    return value;
}

// A `map_Kd [options] file` statement: options start with '-' and take the numbers (or on/off)
// after them; what remains, joined by single spaces, is the file. `-clamp on` clamps the texture.
struct TextureMap {
    std::string file;
    bool clamp = false;
};

TextureMap textureMap(const std::vector<std::string_view>& words) {
    TextureMap map;
    for (std::size_t i = 1; i < words.size(); ++i) {
        if (map.file.empty() && words[i].starts_with('-')) {
            if (words[i] == "-clamp" && i + 1 < words.size()) map.clamp = words[i + 1] == "on";
            while (i + 1 < words.size() &&
                   (number(words[i + 1]) || words[i + 1] == "on" || words[i + 1] == "off"))
                ++i;
            continue;
        }
        map.file += (map.file.empty() ? "" : " ") + std::string(words[i]);
    }
    return map;
}

// sRGB-coded display colour (what .mtl files hold) to the linear factor SurfaceMaterial keeps.
float linear(float c) {
    return std::pow(std::clamp(c, 0.0f, 1.0f), 2.2f);
}

class MtlReader {
  public:
    explicit MtlReader(ObjSurface& out) : out_(out) {}

    void read(const std::filesystem::path& file, const std::string& where) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec)) {
            out_.materials.warnings.push_back(where + ": material library '" + file.string() +
                                              "' not found; its materials are drawn in white");
            return;
        }
        const std::string text = readFileToString(file);
        const std::string source = file.string();
        SurfaceMaterial* current = nullptr;
        forEachLine(text, [&](std::size_t line, std::string_view content) {
            const auto words = tokens(content);
            if (words.empty()) return;
            const std::string at = fileLine(source, line);
            if (words[0] == "newmtl") {
                const std::string name = words.size() > 1 ? std::string(words[1]) : std::string();
                byName_[name] = static_cast<int>(out_.materials.materials.size());
                out_.materials.materials.push_back({});
                current = &out_.materials.materials.back();
                current->name = name;
                return;
            }
            if (!current) return;
            if (words[0] == "Kd" && words.size() >= 4) {
                for (int k = 0; k < 3; ++k) {
                    const auto c = number(words[static_cast<std::size_t>(k + 1)]);
                    if (!c) throwInputError(at, "Kd needs 3 numbers, got '" + std::string(content) + "'");
                    kd_[current->name][static_cast<std::size_t>(k)] = linear(*c);
                }
            } else if ((words[0] == "d" || words[0] == "Tr") && words.size() >= 2) {
                const auto value = number(words.back());
                if (!value) throwInputError(at, std::string(words[0]) + " needs a number");
                current->baseColor[3] = std::clamp(words[0] == "d" ? *value : 1.0f - *value, 0.0f, 1.0f);
                if (current->baseColor[3] < 1.0f) current->alphaMode = AlphaMode::Blend;
            } else if (words[0] == "map_Kd") {
                const TextureMap map = textureMap(words);
                if (map.file.empty()) throwInputError(at, "map_Kd names no file");
                current->image = image(file.parent_path() / map.file, at);
                current->wrapU = current->wrapV = map.clamp ? TextureWrap::Clamp : TextureWrap::Repeat;
            }
        });
        for (SurfaceMaterial& m : out_.materials.materials)
            if (m.image < 0 && kd_.count(m.name))
                for (std::size_t k = 0; k < 3; ++k) m.baseColor[k] = kd_[m.name][k];
    }

    int material(const std::string& name) const {
        const auto it = byName_.find(name);
        return it == byName_.end() ? -1 : it->second;
    }

  private:
    // The image of a texture file (each file decoded once), or -1 with a warning.
    int image(const std::filesystem::path& file, const std::string& at) {
        const std::string key = file.lexically_normal().string();
        if (const auto it = images_.find(key); it != images_.end()) return it->second;
        int index = -1;
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec)) {
            out_.materials.warnings.push_back(at + ": texture '" + file.string() +
                                              "' not found; drawn in the material's colour");
        } else {
            DecodedImage decoded =
                decodeImage(readFileToString(file), at + ": texture '" + file.string() + "'",
                            kMaxTextureBytes - usedBytes_);
            if (decoded.image) {
                usedBytes_ += decoded.image->rgba.size();
                decoded.image->name = file.filename().string();
                index = static_cast<int>(out_.materials.images.size());
                out_.materials.images.push_back(std::move(*decoded.image));
            } else {
                out_.materials.warnings.push_back(at + ": texture '" + file.string() + "' not drawn: " +
                                                  decoded.problem + "; drawn in the material's colour");
            }
        }
        images_[key] = index;
        return index;
    }

    ObjSurface& out_;
    std::map<std::string, int> byName_, images_;
    std::map<std::string, std::array<float, 3>> kd_; // kept apart: a map_Kd replaces the colour
    std::size_t usedBytes_ = 0;
};

} // namespace

ObjSurface parseObjSurface(std::string_view objText, std::string_view source,
                           const std::filesystem::path& folder) {
    // Most OBJ files name no material: not worth parsing a second time.
    if (objText.find("mtllib") == std::string_view::npos && objText.find("usemtl") == std::string_view::npos)
        return {};
    CornerTexCoords corners;
    const MeshData mesh = parseObj(objText, source, corners);
    ObjSurface out;
    MtlReader libraries(out);
    std::vector<std::pair<std::size_t, std::string>> uses; // (first triangle, material name)
    std::vector<std::size_t> useLines;
    std::size_t triangles = 0;
    bool anyLibrary = false;
    forEachLine(objText, [&](std::size_t line, std::string_view content) {
        const auto words = tokens(content);
        if (words.empty()) return;
        if (words[0] == "f" || words[0] == "fo") {
            triangles += words.size() - 3; // parseObj accepted it: a fan of corners - 2 triangles
        } else if (words[0] == "mtllib") {
            anyLibrary = true;
            for (std::size_t i = 1; i < words.size(); ++i)
                libraries.read(folder / std::string(words[i]), fileLine(source, line));
        } else if (words[0] == "usemtl") {
            uses.emplace_back(triangles, words.size() > 1 ? std::string(words[1]) : std::string());
            useLines.push_back(line);
        }
    });
    if (triangles != mesh.triangles.size()) // the two readings of one text must agree
        throwInputError(source, "counted " + std::to_string(triangles) +
                                    " triangles for materials, the mesh has " +
                                    std::to_string(mesh.triangles.size()));
    if (!anyLibrary && uses.empty()) return {};
    SurfaceLayout& layout = out.layout;
    std::size_t start = 0;
    int material = -1;
    const auto close = [&](std::size_t end) {
        if (end > start) layout.ranges.push_back({start, end - start, material});
        start = end;
    };
    for (std::size_t u = 0; u < uses.size(); ++u) {
        close(uses[u].first);
        material = libraries.material(uses[u].second);
        if (material < 0)
            out.materials.warnings.push_back(fileLine(source, useLines[u]) + ": usemtl '" + uses[u].second +
                                             "' names no material of the mtllib files; drawn in white");
    }
    close(triangles);
    if (!corners.texCoords.empty()) {
        for (const Vec2& t : corners.texCoords) layout.texCoords.emplace_back(t[0], 1.0 - t[1]);
        const auto missing = static_cast<std::uint32_t>(layout.texCoords.size());
        layout.texCoords.emplace_back(0.0, 0.0); // for corners without a texture coordinate
        layout.cornerTexCoords = corners.triangles;
        for (Triangle& t : layout.cornerTexCoords)
            for (std::uint32_t& c : t)
                if (c == CornerTexCoords::kNoTexCoord) c = missing;
    }
    return out;
}

ObjSurface readObjSurface(const std::filesystem::path& objPath) {
    return parseObjSurface(readFileToString(objPath), objPath.string(),
                           objPath.parent_path().empty() ? "." : objPath.parent_path());
}

} // namespace vl
