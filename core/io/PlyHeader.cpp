#include "core/io/PlyHeader.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"

#include <algorithm>
#include <array>
#include <utility>

namespace vl::meshio {

namespace {

// Both the PLY 1.0 names and the sized aliases (int8, float32, ...) that many writers use.
constexpr std::array<std::pair<std::string_view, PlyType>, 16> kTypeNames{{
    {"char", PlyType::Int8},
    {"int8", PlyType::Int8},
    {"uchar", PlyType::UInt8},
    {"uint8", PlyType::UInt8},
    {"short", PlyType::Int16},
    {"int16", PlyType::Int16},
    {"ushort", PlyType::UInt16},
    {"uint16", PlyType::UInt16},
    {"int", PlyType::Int32},
    {"int32", PlyType::Int32},
    {"uint", PlyType::UInt32},
    {"uint32", PlyType::UInt32},
    {"float", PlyType::Float32},
    {"float32", PlyType::Float32},
    {"double", PlyType::Float64},
    {"float64", PlyType::Float64},
}};

PlyType typeFromName(std::string_view name, const std::string& where) {
    for (const auto& [typeName, type] : kTypeNames)
        if (typeName == name) return type;
    throwInputError(where, "unknown PLY property type '" + std::string(name) + "'");
}

} // namespace

std::size_t plyTypeSize(PlyType type) {
    switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8:
        return 1;
    case PlyType::Int16:
    case PlyType::UInt16:
        return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32:
        return 4;
    case PlyType::Float64:
        return 8;
    }
    return 0;
}

bool isPlyIntegerType(PlyType type) {
    return type != PlyType::Float32 && type != PlyType::Float64;
}

int PlyElement::find(std::string_view propertyName) const {
    for (std::size_t i = 0; i < properties.size(); ++i)
        if (properties[i].name == propertyName) return static_cast<int>(i);
    return -1;
}

const PlyElement* PlyHeader::find(std::string_view elementName) const {
    for (const auto& element : elements)
        if (element.name == elementName) return &element;
    return nullptr;
}

PlyHeader parsePlyHeader(std::string_view bytes, std::string_view source) {
    PlyHeader header;
    bool sawFormat = false;
    std::size_t pos = 0;
    for (std::size_t lineNumber = 1;; ++lineNumber) {
        if (pos >= bytes.size())
            throwInputError(source, "PLY header has no end_header line (file truncated?)");
        const std::size_t newline = bytes.find('\n', pos);
        const std::size_t end = newline == std::string_view::npos ? bytes.size() : newline;
        const std::string_view line = bytes.substr(pos, end - pos);
        pos = end + 1;
        const std::string where = fileLine(source, lineNumber);
        const auto tokens = splitWhitespace(line);
        if (lineNumber == 1) {
            if (tokens.size() != 1 || tokens[0] != "ply")
                throwInputError(where, "not a PLY file (no 'ply' first line)");
            continue;
        }
        if (tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info") continue;
        if (tokens[0] == "end_header") {
            if (!sawFormat) throwInputError(where, "PLY header has no format line");
            header.dataOffset = std::min(pos, bytes.size());
            header.dataLine = lineNumber + 1;
            return header;
        }
        if (tokens[0] == "format") {
            if (tokens.size() != 3) throwInputError(where, "expected 'format <encoding> 1.0'");
            if (tokens[1] == "ascii")
                header.encoding = PlyEncoding::Ascii;
            else if (tokens[1] == "binary_little_endian")
                header.encoding = PlyEncoding::BinaryLittleEndian;
            else if (tokens[1] == "binary_big_endian")
                header.encoding = PlyEncoding::BinaryBigEndian;
            else
                throwInputError(where, "unknown PLY encoding '" + std::string(tokens[1]) + "'");
            sawFormat = true;
        } else if (tokens[0] == "element") {
            if (tokens.size() != 3) throwInputError(where, "expected 'element <name> <count>'");
            const std::int64_t count = parseInteger(tokens[2], where);
            if (count < 0) throwInputError(where, "negative element count " + std::to_string(count));
            header.elements.push_back(
                {std::string(tokens[1]), static_cast<std::size_t>(count), {}, lineNumber});
        } else if (tokens[0] == "property") {
            if (header.elements.empty()) throwInputError(where, "property before any element");
            PlyProperty property;
            if (tokens.size() == 5 && tokens[1] == "list") {
                property.isList = true;
                property.countType = typeFromName(tokens[2], where);
                property.type = typeFromName(tokens[3], where);
                property.name = tokens[4];
                if (!isPlyIntegerType(property.countType))
                    throwInputError(where, "list length type must be an integer type");
            } else if (tokens.size() == 3) {
                property.type = typeFromName(tokens[1], where);
                property.name = tokens[2];
            } else {
                throwInputError(where,
                                "expected 'property <type> <name>' or 'property list <type> <type> <name>'");
            }
            header.elements.back().properties.push_back(std::move(property));
        } else {
            throwInputError(where, "unknown PLY header line '" + std::string(trim(line)) + "'");
        }
    }
}

} // namespace vl::meshio
