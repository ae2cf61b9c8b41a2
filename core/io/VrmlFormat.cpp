// VRML97 IndexedFaceSet reader and writer. The reader does not build a scene graph: it scans the
// tokens for IndexedFaceSet nodes (wherever they are nested) and for DEF'd Coordinate and
// TextureCoordinate nodes that a later `USE` may name, and skips everything else.
#include "core/common/Error.h"
#include "core/common/Limits.h"
#include "core/io/MeshIO.h"
#include "core/io/MeshIOSupport.h"
#include "core/io/VrmlTokenizer.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace vl {

using meshio::VrmlToken;

namespace {

struct PointNode {
    std::string_view type; // "Coordinate" or "TextureCoordinate"
    std::vector<double> values;
};

struct IndexEntry {
    std::int64_t value;
    std::size_t line;
};

struct FaceSet {
    std::size_t line = 0;
    std::vector<double> points;    // x y z ...
    std::vector<double> texPoints; // u v ...
    bool hasTexCoord = false;
    std::vector<IndexEntry> coordIndex;
    std::vector<IndexEntry> texCoordIndex;
    std::size_t texCoordIndexLine = 0;
};

bool looksNumeric(std::string_view token) {
    return !token.empty() && (std::isdigit(static_cast<unsigned char>(token[0])) || token[0] == '-' ||
                              token[0] == '+' || token[0] == '.');
}

class VrmlParser {
  public:
    VrmlParser(std::string_view text, std::string_view source, CornerTexCoords* corners)
        : source_(source), tokens_(meshio::tokenizeVrml(text, source)), cornerTexCoords_(corners) {}

    MeshData run() {
        while (i_ < tokens_.size()) {
            const std::string_view t = tokens_[i_].text;
            if (t == "PROTO" || t == "EXTERNPROTO")
                skipProto();
            else if (t == "DEF" && (peek(2) == "Coordinate" || peek(2) == "TextureCoordinate"))
                parsePointNode(peek(2), peek(2) == "Coordinate" ? 3 : 2);
            else if (t == "DEF" || t == "USE")
                i_ += 2; // a name, never a keyword
            else if (t == "IndexedFaceSet" && peek(1) == "{")
                appendFaceSet(parseFaceSet());
            else
                ++i_;
        }
        if (faceSets_ == 0) throwInputError(source_, "no IndexedFaceSet found (no vertices)");
        meshio::requireVerticesAndFaces(mesh_, source_);
        cornerUV_.resize(mesh_.positions.size(), -1);
        mesh_.uvs = meshio::uvsFromFirstCorners(cornerUV_, texCoords_);
        if (cornerTexCoords_) {
            if (mesh_.uvs.empty())
                *cornerTexCoords_ = {};
            else
                cornerTexCoords_->texCoords = texCoords_;
        }
        return std::move(mesh_);
    }

  private:
    std::string_view peek(std::size_t ahead) const {
        return i_ + ahead < tokens_.size() ? tokens_[i_ + ahead].text : std::string_view{};
    }
    std::string whereLine(std::size_t line) const { return fileLine(source_, line); }
    std::size_t useBudget() const {
        return std::max(limits::kVrmlMinUseExpansionBudget, limits::kVrmlUseExpansionFactor * tokens_.size());
    }
    std::string here() const { return whereLine(i_ < tokens_.size() ? tokens_[i_].line : lastLine()); }
    std::size_t lastLine() const { return tokens_.empty() ? 1 : tokens_.back().line; }

    const VrmlToken& take(std::string_view expecting) {
        if (i_ >= tokens_.size())
            throwInputError(here(), "unexpected end of file, expected " + std::string(expecting));
        return tokens_[i_++];
    }
    void expect(std::string_view text) {
        const VrmlToken& token = take("'" + std::string(text) + "'");
        if (token.text != text)
            throwInputError(whereLine(token.line),
                            "expected '" + std::string(text) + "', found '" + std::string(token.text) + "'");
    }

    // Skips a balanced { } or [ ] group starting at the current token.
    void skipGroup() {
        int depth = 0;
        do {
            const std::string_view t = take("a closing bracket").text;
            if (t == "{" || t == "[")
                ++depth;
            else if (t == "}" || t == "]")
                --depth;
        } while (depth > 0);
    }

    // PROTO name [ interface ] { body } / EXTERNPROTO name [ interface ] url: bodies are templates,
    // not geometry.
    void skipProto() {
        const bool external = take("PROTO").text == "EXTERNPROTO";
        take("a PROTO name");
        if (peek(0) == "[") skipGroup();
        if (external) {
            if (peek(0) == "[")
                skipGroup();
            else
                take("a URL");
        } else if (peek(0) == "{") {
            skipGroup();
        }
    }

    // Skips one field value: [ ... ], a node (DEF/USE/Type { ... }), or a single value with
    // any numbers that follow it (SFVec3f and friends).
    void skipFieldValue() {
        const std::string_view t = peek(0);
        if (t == "[") return skipGroup();
        if (t == "USE") {
            i_ += 2;
            return;
        }
        if (t == "DEF") i_ += 2;
        if (peek(1) == "{") {
            ++i_;
            return skipGroup();
        }
        take("a field value");
        while (looksNumeric(peek(0))) ++i_;
    }

    std::vector<double> parseNumbers(std::size_t singleValueCount) {
        std::vector<double> values;
        const auto read = [&](const VrmlToken& token) {
            values.push_back(meshio::toFiniteDouble(token.text, [&] { return whereLine(token.line); }));
        };
        if (peek(0) != "[") {
            for (std::size_t k = 0; k < singleValueCount; ++k) read(take("a number"));
            return values;
        }
        ++i_;
        while (peek(0) != "]") read(take("']'"));
        ++i_;
        return values;
    }

    std::vector<IndexEntry> parseIndices() {
        std::vector<IndexEntry> entries;
        const auto read = [&](const VrmlToken& token) {
            entries.push_back(
                {meshio::toInteger(token.text, [&] { return whereLine(token.line); }), token.line});
        };
        if (peek(0) != "[") {
            read(take("an index"));
            return entries;
        }
        ++i_;
        while (peek(0) != "]") read(take("']'"));
        ++i_;
        return entries;
    }

    // A Coordinate or TextureCoordinate field value: NULL, USE name, or [DEF name] Type { point [...] }.
    std::vector<double> parsePointNode(std::string_view type, std::size_t dims) {
        const VrmlToken& first = take(type);
        if (first.text == "NULL") return {};
        if (first.text == "USE") {
            const VrmlToken& name = take("a node name");
            const auto it = defs_.find(std::string(name.text));
            if (it == defs_.end())
                throwInputError(whereLine(name.line),
                                "USE of unknown " + std::string(type) + " '" + std::string(name.text) + "'");
            if (it->second.type != type)
                throwInputError(whereLine(name.line), "'" + std::string(name.text) + "' is a " +
                                                          std::string(it->second.type) + ", not a " +
                                                          std::string(type));
            // Each USE copies the points again: a small file must not expand into gigabytes.
            usedValues_ += it->second.values.size();
            if (usedValues_ > useBudget())
                throwInputError(
                    whereLine(name.line),
                    "USE of '" + std::string(name.text) + "' would copy " + std::to_string(usedValues_) +
                        " numbers in total by USE, more than the limit of " + std::to_string(useBudget()) +
                        " for this file (" + std::to_string(limits::kVrmlUseExpansionFactor) + " per token)");
            return it->second.values;
        }
        std::string defName;
        const VrmlToken* typeToken = &first;
        if (first.text == "DEF") {
            defName = take("a node name").text;
            typeToken = &take(type);
        }
        if (typeToken->text != type)
            throwInputError(whereLine(typeToken->line), "expected a " + std::string(type) + " node, found '" +
                                                            std::string(typeToken->text) + "'");
        expect("{");
        std::vector<double> values;
        std::size_t pointLine = typeToken->line;
        while (peek(0) != "}") {
            const VrmlToken& field = take("'}'");
            if (field.text == "point") {
                pointLine = field.line;
                values = parseNumbers(dims);
            } else {
                skipFieldValue();
            }
        }
        ++i_;
        if (values.size() % dims != 0)
            throwInputError(whereLine(pointLine), "point list has " + std::to_string(values.size()) +
                                                      " numbers, not a multiple of " + std::to_string(dims));
        if (!defName.empty()) defs_[defName] = {type, values};
        return values;
    }

    FaceSet parseFaceSet() {
        FaceSet set;
        set.line = tokens_[i_].line;
        i_ += 2; // IndexedFaceSet {
        while (peek(0) != "}") {
            const VrmlToken& field =
                take("'}' closing the IndexedFaceSet of line " + std::to_string(set.line));
            if (field.text == "coord") {
                set.points = parsePointNode("Coordinate", 3);
            } else if (field.text == "texCoord") {
                set.texPoints = parsePointNode("TextureCoordinate", 2);
                set.hasTexCoord = !set.texPoints.empty(); // `texCoord NULL` means none
            } else if (field.text == "coordIndex") {
                set.coordIndex = parseIndices();
            } else if (field.text == "texCoordIndex") {
                set.texCoordIndexLine = field.line;
                set.texCoordIndex = parseIndices();
            } else {
                skipFieldValue();
            }
        }
        ++i_;
        return set;
    }

    // Checks one coordIndex/texCoordIndex entry against `count` items: -1 ends a face, anything
    // else must index an item.
    void checkIndex(const IndexEntry& entry, std::size_t count, const char* what) const {
        if (entry.value < -1)
            throwInputError(whereLine(entry.line), "negative " + std::string(what) + " index " +
                                                       std::to_string(entry.value) +
                                                       " (only -1, which ends a face, is allowed)");
        if (entry.value >= 0 && static_cast<std::uint64_t>(entry.value) >= count)
            throwInputError(whereLine(entry.line), std::string(what) + " index " +
                                                       std::to_string(entry.value) + " out of range (" +
                                                       std::to_string(count) + " points)");
    }

    void appendFaceSet(const FaceSet& set) {
        ++faceSets_;
        const std::size_t vertexOffset = mesh_.positions.size();
        const std::size_t texOffset = texCoords_.size();
        const std::size_t pointCount = set.points.size() / 3;
        const std::size_t texCount = set.texPoints.size() / 2;
        for (std::size_t k = 0; k < pointCount; ++k)
            mesh_.positions.emplace_back(set.points[3 * k], set.points[3 * k + 1], set.points[3 * k + 2]);
        for (std::size_t k = 0; k < texCount; ++k)
            texCoords_.emplace_back(set.texPoints[2 * k], set.texPoints[2 * k + 1]);
        cornerUV_.resize(mesh_.positions.size(), -1);

        // A texCoordIndex equal to coordIndex (what VisemeLab writes for XfacePlayer) means per-vertex
        // texture coordinates, so vertices no face uses keep theirs too.
        const bool sameAsCoordIndex =
            set.texCoordIndex.size() == set.coordIndex.size() &&
            std::equal(set.texCoordIndex.begin(), set.texCoordIndex.end(), set.coordIndex.begin(),
                       [](const IndexEntry& a, const IndexEntry& b) { return a.value == b.value; });
        const bool separateTexIndex = set.hasTexCoord && !set.texCoordIndex.empty() && !sameAsCoordIndex;
        if (separateTexIndex) {
            bool matches = set.texCoordIndex.size() == set.coordIndex.size();
            for (std::size_t k = 0; matches && k < set.coordIndex.size(); ++k)
                matches = (set.coordIndex[k].value == -1) == (set.texCoordIndex[k].value == -1);
            if (!matches)
                throwInputError(whereLine(set.texCoordIndexLine),
                                "texCoordIndex does not have the same faces as coordIndex (" +
                                    std::to_string(set.texCoordIndex.size()) + " vs " +
                                    std::to_string(set.coordIndex.size()) + " entries)");
        }
        if (set.hasTexCoord && !separateTexIndex) // coordIndex indexes the texture coordinates too
            for (std::size_t k = 0; k < std::min(pointCount, texCount); ++k)
                cornerUV_[vertexOffset + k] = static_cast<std::int64_t>(texOffset + k);
        std::vector<std::uint32_t> corners, texCorners;
        std::vector<Triangle> triangles;
        for (std::size_t k = 0; k < set.coordIndex.size(); ++k) {
            const IndexEntry& entry = set.coordIndex[k];
            checkIndex(entry, pointCount, "coordIndex");
            if (set.hasTexCoord)
                checkIndex(separateTexIndex ? set.texCoordIndex[k] : entry, texCount, "texture coordinate");
            if (entry.value >= 0) {
                corners.push_back(static_cast<std::uint32_t>(entry.value));
                auto& uv = cornerUV_[vertexOffset + static_cast<std::size_t>(entry.value)];
                if (separateTexIndex && uv < 0) // first corner wins
                    uv = static_cast<std::int64_t>(texOffset) + set.texCoordIndex[k].value;
                const std::int64_t texture = !set.hasTexCoord   ? -1
                                             : separateTexIndex ? set.texCoordIndex[k].value
                                                                : entry.value;
                texCorners.push_back(texture < 0 ? CornerTexCoords::kNoTexCoord
                                                 : static_cast<std::uint32_t>(texOffset + texture));
            }
            // The last face may omit its closing -1.
            if (entry.value == -1 || k + 1 == set.coordIndex.size()) {
                const std::string problem = meshio::appendPolygonFan(corners, faceCount_++, 0, triangles);
                if (!problem.empty()) throwInputError(whereLine(entry.line), problem);
                if (cornerTexCoords_) // the same fan over the texture corners
                    for (std::size_t c = 2; c < texCorners.size(); ++c)
                        cornerTexCoords_->triangles.push_back(
                            {texCorners[0], texCorners[c - 1], texCorners[c]});
                corners.clear();
                texCorners.clear();
            }
        }
        for (const auto& t : triangles)
            mesh_.triangles.push_back({static_cast<std::uint32_t>(t[0] + vertexOffset),
                                       static_cast<std::uint32_t>(t[1] + vertexOffset),
                                       static_cast<std::uint32_t>(t[2] + vertexOffset)});
    }

    std::string_view source_;
    std::vector<VrmlToken> tokens_;
    std::size_t i_ = 0;
    std::map<std::string, PointNode> defs_;
    std::size_t usedValues_ = 0; // numbers copied by USE so far
    std::size_t faceSets_ = 0;
    std::size_t faceCount_ = 0;
    MeshData mesh_;
    std::vector<Vec2> texCoords_;
    std::vector<std::int64_t> cornerUV_;
    CornerTexCoords* cornerTexCoords_; // filled when the caller asks for corner texture coordinates
};

} // namespace

namespace {

MeshData parseVrmlText(std::string_view text, std::string_view source, CornerTexCoords* corners) {
    meshio::requireNotBlank(text, source);
    if (text.size() >= 2 && static_cast<unsigned char>(text[0]) == 0x1f &&
        static_cast<unsigned char>(text[1]) == 0x8b)
        throwInputError(source, "gzip-compressed VRML is not supported; decompress it first (gunzip)");
    if (text.starts_with("#VRML V1.0"))
        throwInputError(fileLine(source, 1), "VRML 1.0 is not supported; only VRML97 (#VRML V2.0 utf8)");
    return VrmlParser(text, source, corners).run();
}

} // namespace

MeshData parseVrml(std::string_view text, std::string_view source) {
    return parseVrmlText(text, source, nullptr);
}

MeshData parseVrml(std::string_view text, std::string_view source, CornerTexCoords& corners) {
    corners = {};
    return parseVrmlText(text, source, &corners);
}

// The layout XfacePlayer's VRML loader reads (it loops on other legal VRML97): values separated by
// commas, a comma after every index including each face's -1, no comma before a closing ']', and
// an explicit texCoordIndex when there are texture coordinates. Any VRML97 reader reads it too.
// XfacePlayer reads tokens with `>>`, so a comma must be followed by white space (here a space or a
// line end) and indentation does not matter: the long point and index lists are written without it,
// one point or face per line (a seventh of a key mesh's bytes).
std::string formatVrml(const MeshData& mesh) {
    meshio::requireWritable(mesh);
    return meshio::joinAroundPositions(meshio::vrmlTextAroundPositions(mesh),
                                       PositionText(mesh.positions, PositionPrecision::Exact),
                                       meshio::appendVrmlPositions);
}

namespace meshio {

TextAroundPositions vrmlTextAroundPositions(const MeshData& topology) {
    TextAroundPositions parts;
    parts.head = "#VRML V2.0 utf8\n# VisemeLab mesh: " + std::to_string(topology.positions.size()) +
                 " vertices, " + std::to_string(topology.triangles.size()) +
                 " triangles\n"
                 "Shape {\n  appearance Appearance { material Material { } }\n  geometry IndexedFaceSet {\n"
                 "    solid FALSE\n    coord Coordinate {\n      point [\n";
    std::string& out = parts.tail;
    out.reserve(topology.uvs.size() * 50 + topology.triangles.size() * (topology.hasUVs() ? 120 : 60));
    out += "      ]\n    }\n";
    if (topology.hasUVs()) {
        out += "    texCoord TextureCoordinate {\n      point [\n";
        for (std::size_t i = 0; i < topology.uvs.size(); ++i)
            appendDoubles(out, "", {topology.uvs[i][0], topology.uvs[i][1]},
                          i + 1 < topology.uvs.size() ? ",\n" : "\n");
        out += "      ]\n    }\n";
    }
    // The faces' index list, formatted once for coordIndex and texCoordIndex.
    std::string indices;
    indices.reserve(topology.triangles.size() * 30);
    for (std::size_t t = 0; t < topology.triangles.size(); ++t) {
        for (const auto v : topology.triangles[t]) {
            appendInteger(indices, static_cast<std::int64_t>(v));
            indices += ", ";
        }
        indices += t + 1 < topology.triangles.size() ? "-1,\n" : "-1\n";
    }
    const auto indexList = [&](std::string_view field) {
        out += "    ";
        out += field;
        out += " [\n";
        out += indices;
        out += "    ]\n";
    };
    indexList("coordIndex");
    if (topology.hasUVs()) indexList("texCoordIndex"); // per-vertex (u,v): the same indices
    out += "  }\n}\n";
    return parts;
}

void appendVrmlPositions(std::string& out, const PositionText& positions) {
    positions.appendLines(out, "", ",\n", "\n");
}

} // namespace meshio

} // namespace vl
