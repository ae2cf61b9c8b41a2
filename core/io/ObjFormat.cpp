// Wavefront OBJ reader and writer. Hand-written rather than OpenMesh's reader, which may reorder
// or split vertices that carry texture coordinates; here the i-th `v` line is vertex i, always.
#include "core/common/Error.h"
#include "core/io/MeshIO.h"
#include "core/io/MeshIOSupport.h"

#include <cstring>
#include <limits>

namespace vl {

namespace {

bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// The next whitespace-separated token of `line` at or after `pos`; empty at the end of the line.
std::string_view nextToken(std::string_view line, std::size_t& pos) {
    while (pos < line.size() && isSpace(line[pos])) ++pos;
    const std::size_t start = pos;
    while (pos < line.size() && !isSpace(line[pos])) ++pos;
    return line.substr(start, pos - start);
}

class ObjParser {
  public:
    ObjParser(std::string_view text, std::string_view source, CornerTexCoords* corners)
        : text_(text), source_(source), cornerTexCoords_(corners) {}

    MeshData run() {
        meshio::requireNotBlank(text_, source_);
        forEachLine(text_, [this](std::string_view line) {
            ++line_;
            parseLine(line);
            return true;
        });
        return finish();
    }

    // The `v` lines' positions when every other line equals the structure's line (see objStructure).
    std::optional<std::vector<Vec3>> positionsMatching(std::string_view structure) {
        meshio::requireNotBlank(text_, source_);
        std::size_t at = 0; // read position in `structure`
        const bool same = forEachLine(text_, [&](std::string_view line) {
            ++line_;
            const std::size_t newline = structure.find('\n', at);
            if (newline == std::string_view::npos) return false; // more lines than the reference
            const std::string_view expected = structure.substr(at, newline - at);
            at = newline + 1;
            if (!isVertexLine(line)) return line == expected;
            if (expected != "v") return false;
            // Tokens end at a comment as in parseLine: in "v#1 2 3" the keyword token is "v".
            const std::string_view statement = line.substr(0, line.find('#'));
            std::size_t pos = 0;
            (void)nextToken(statement, pos);
            parseVertex(statement, pos);
            return true;
        });
        if (!same || at != structure.size()) return std::nullopt;
        return std::move(mesh_.positions);
    }

    static bool isVertexLine(std::string_view line) {
        line = line.substr(0, line.find('#'));
        std::size_t pos = 0;
        return nextToken(line, pos) == "v";
    }

    // Calls visit(line) for each line after a UTF-8 byte order mark; stops when it returns false.
    template <typename Visit> static bool forEachLine(std::string_view text, Visit&& visit) {
        std::size_t pos = text.starts_with("\xEF\xBB\xBF") ? 3 : 0;
        while (pos < text.size()) {
            const void* newline = std::memchr(text.data() + pos, '\n', text.size() - pos);
            const std::size_t end =
                newline ? static_cast<std::size_t>(static_cast<const char*>(newline) - text.data())
                        : text.size();
            if (!visit(text.substr(pos, end - pos))) return false;
            pos = end + 1;
        }
        return true;
    }

  private:
    // A positive index naming an element defined later in the file; checked once all are known.
    struct ForwardReference {
        std::size_t line;
        std::int64_t index;
        bool texture;
    };

    std::string where() const { return fileLine(source_, line_); }

    void parseLine(std::string_view line) {
        line = line.substr(0, line.find('#')); // comments, also at the end of a statement
        std::size_t pos = 0;
        const std::string_view keyword = nextToken(line, pos);
        if (keyword == "v") {
            parseVertex(line, pos);
        } else if (keyword == "vt") {
            parseTexCoord(line, pos);
        } else if (keyword == "f" || keyword == "fo") { // "fo" is the old spelling of "f"
            parseFace(line, pos);
        } else if (keyword != "vn" && keyword != "vp" && !keyword.empty() &&
                   (keyword[0] == 'v' || keyword[0] == 'V' || keyword[0] == 'f' || keyword[0] == 'F')) {
            // Skipping something that may be a vertex or face would silently renumber the rest.
            throwInputError(where(), "unknown OBJ statement '" + std::string(keyword) + "'");
        }
        // Everything else (vn, vp, o, g, s, usemtl, mtllib, l, ...) does not change the mesh.
    }

    void parseVertex(std::string_view line, std::size_t pos) {
        const auto at = [this] { return where(); };
        Vec3 p;
        for (int k = 0; k < 3; ++k) {
            const std::string_view token = nextToken(line, pos);
            if (token.empty())
                throwInputError(where(), "a vertex needs 3 coordinates, found " + std::to_string(k));
            p[k] = meshio::toFiniteDouble(token, at);
        }
        // An optional w or per-vertex colour may follow; the mesh has no use for them.
        mesh_.positions.push_back(p);
    }

    void parseTexCoord(std::string_view line, std::size_t pos) {
        const auto at = [this] { return where(); };
        const std::string_view u = nextToken(line, pos);
        if (u.empty()) throwInputError(where(), "a texture coordinate needs at least u");
        const std::string_view v = nextToken(line, pos); // v is optional in OBJ and then 0
        texCoords_.emplace_back(meshio::toFiniteDouble(u, at),
                                v.empty() ? 0.0 : meshio::toFiniteDouble(v, at));
    }

    // Turns a 1-based or negative (relative) OBJ index into a 0-based one.
    std::int64_t resolveIndex(std::string_view token, std::size_t definedSoFar, bool texture) {
        const char* what = texture ? "texture coordinate" : "vertex";
        const std::int64_t index = meshio::toInteger(token, [this] { return where(); });
        if (index == 0)
            throwInputError(where(), std::string(what) + " index 0 is invalid (OBJ indices start at 1)");
        if (index < 0) {
            const auto resolved = static_cast<std::int64_t>(definedSoFar) + index;
            if (resolved < 0)
                throwInputError(where(), "relative " + std::string(what) + " index " + std::to_string(index) +
                                             " points before the first one (" + std::to_string(definedSoFar) +
                                             " defined so far)");
            return resolved;
        }
        if (index > std::numeric_limits<std::uint32_t>::max())
            throwInputError(where(), std::string(what) + " index " + std::to_string(index) + " out of range");
        if (static_cast<std::size_t>(index) > definedSoFar) forward_.push_back({line_, index, texture});
        return index - 1;
    }

    void parseFace(std::string_view line, std::size_t pos) {
        corners_.clear();
        texCorners_.clear();
        for (std::string_view token = nextToken(line, pos); !token.empty(); token = nextToken(line, pos)) {
            // Corner forms: v, v/vt, v//vn, v/vt/vn. Normals are not used.
            const std::size_t slash = token.find('/');
            const std::string_view vertexToken = token.substr(0, slash);
            std::string_view textureToken;
            bool malformed = vertexToken.empty();
            if (slash != std::string_view::npos) {
                const std::string_view rest = token.substr(slash + 1);
                const std::size_t slash2 = rest.find('/');
                textureToken = rest.substr(0, slash2);
                malformed |=
                    slash2 == std::string_view::npos ? textureToken.empty() : slash2 + 1 == rest.size();
            }
            if (malformed) throwInputError(where(), "malformed face corner '" + std::string(token) + "'");
            const auto v =
                static_cast<std::uint32_t>(resolveIndex(vertexToken, mesh_.positions.size(), false));
            corners_.push_back(v);
            std::int64_t t = -1;
            if (!textureToken.empty()) {
                t = resolveIndex(textureToken, texCoords_.size(), true);
                if (v < mesh_.positions.size()) {
                    // Grown only to vertices that exist: a huge index in a tiny file allocates nothing.
                    if (v >= cornerUV_.size()) cornerUV_.resize(mesh_.positions.size(), -1);
                    if (cornerUV_[v] < 0) cornerUV_[v] = t; // first corner wins at UV seams
                } else {
                    forwardUV_.push_back({v, t});
                }
            }
            texCorners_.push_back(t < 0 ? CornerTexCoords::kNoTexCoord : static_cast<std::uint32_t>(t));
        }
        const std::string problem = meshio::appendPolygonFan(corners_, faceCount_++, 1, mesh_.triangles);
        if (!problem.empty()) throwInputError(where(), problem);
        if (cornerTexCoords_) // the same fan over the texture corners
            for (std::size_t k = 2; k < texCorners_.size(); ++k)
                cornerTexCoords_->triangles.push_back({texCorners_[0], texCorners_[k - 1], texCorners_[k]});
    }

    MeshData finish() {
        for (const auto& ref : forward_) {
            const std::size_t count = ref.texture ? texCoords_.size() : mesh_.positions.size();
            if (static_cast<std::size_t>(ref.index) > count)
                throwInputError(fileLine(source_, ref.line),
                                std::string(ref.texture ? "texture coordinate" : "vertex") + " index " +
                                    std::to_string(ref.index) + " out of range (" + std::to_string(count) +
                                    (ref.texture ? " texture coordinates)" : " vertices)"));
        }
        meshio::requireVerticesAndFaces(mesh_, source_);
        cornerUV_.resize(mesh_.positions.size(), -1);
        // Corners naming a vertex before its `v` line come before every other corner of that vertex
        // in file order, so the earliest of them wins: assign them last, latest first.
        for (auto it = forwardUV_.rbegin(); it != forwardUV_.rend(); ++it)
            cornerUV_[it->vertex] = it->texCoord;
        mesh_.uvs = meshio::uvsFromFirstCorners(cornerUV_, texCoords_);
        if (cornerTexCoords_) {
            if (mesh_.uvs.empty())
                *cornerTexCoords_ = {};
            else
                cornerTexCoords_->texCoords = texCoords_;
        }
        return std::move(mesh_);
    }

    std::string_view text_;
    std::string_view source_;
    std::size_t line_ = 0;
    std::size_t faceCount_ = 0;
    MeshData mesh_;
    std::vector<Vec2> texCoords_;
    std::vector<std::int64_t> cornerUV_; // per vertex (grown on use): first corner's texture coordinate or -1
    std::vector<std::uint32_t> corners_;
    std::vector<std::uint32_t> texCorners_; // the face's texture coordinate per corner, or kNoTexCoord
    CornerTexCoords* cornerTexCoords_;      // filled when the caller asks for corner texture coordinates
    std::vector<ForwardReference> forward_;
    // Texture coordinates of corners whose vertex is defined further down (range-checked in finish()).
    struct ForwardUV {
        std::uint32_t vertex;
        std::int64_t texCoord;
    };
    std::vector<ForwardUV> forwardUV_;
};

} // namespace

MeshData parseObj(std::string_view text, std::string_view source) {
    return ObjParser(text, source, nullptr).run();
}

MeshData parseObj(std::string_view text, std::string_view source, CornerTexCoords& corners) {
    corners = {};
    return ObjParser(text, source, &corners).run();
}

std::string objStructure(std::string_view text) {
    std::string structure;
    // The byte order mark is part of the structure: a file with one and a file without differ.
    if (text.starts_with("\xEF\xBB\xBF")) structure = "\xEF\xBB\xBF\n";
    ObjParser::forEachLine(text, [&](std::string_view line) {
        structure.append(ObjParser::isVertexLine(line) ? std::string_view("v") : line).append("\n");
        return true;
    });
    return structure;
}

std::optional<std::vector<Vec3>> parseObjPositionsMatching(std::string_view text, std::string_view source,
                                                           std::string_view structure) {
    const bool bom = text.starts_with("\xEF\xBB\xBF");
    if (bom != structure.starts_with("\xEF\xBB\xBF\n")) return std::nullopt;
    return ObjParser(text, source, nullptr).positionsMatching(bom ? structure.substr(4) : structure);
}

std::string formatObj(const MeshData& mesh) {
    meshio::requireWritable(mesh);
    return meshio::joinAroundPositions(meshio::objTextAroundPositions(mesh),
                                       PositionText(mesh.positions, PositionPrecision::Exact),
                                       meshio::appendObjPositions);
}

namespace meshio {

TextAroundPositions objTextAroundPositions(const MeshData& topology) {
    TextAroundPositions parts;
    parts.head = "# VisemeLab mesh: " + std::to_string(topology.positions.size()) + " vertices, " +
                 std::to_string(topology.triangles.size()) + " triangles\n";
    std::string& out = parts.tail;
    out.reserve(topology.uvs.size() * 48 + topology.triangles.size() * 40);
    for (const auto& uv : topology.uvs) appendDoubles(out, "vt ", {uv[0], uv[1]}, "\n");
    std::string index;
    for (const auto& t : topology.triangles) {
        out += 'f';
        for (const auto v : t) {
            index.clear();
            appendInteger(index, static_cast<std::int64_t>(v) + 1);
            out += ' ';
            out += index;
            if (topology.hasUVs()) { // the (u,v) of a vertex has its index
                out += '/';
                out += index;
            }
        }
        out += '\n';
    }
    return parts;
}

void appendObjPositions(std::string& out, const PositionText& positions) {
    positions.appendLines(out, "v ", "\n", "\n");
}

} // namespace meshio

} // namespace vl
