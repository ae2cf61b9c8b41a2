#pragma once
// The header of a Stanford PLY file (internal to core/io): encoding, elements and their properties.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace vl::meshio {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

std::size_t plyTypeSize(PlyType type);
bool isPlyIntegerType(PlyType type);

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32; // the item type for a list
    bool isList = false;
    PlyType countType = PlyType::UInt8; // lists only
};

struct PlyElement {
    std::string name;
    std::size_t count = 0;
    std::vector<PlyProperty> properties;
    std::size_t line = 0; // header line of the `element` statement, for messages

    // Index of the property called `name`, or -1.
    int find(std::string_view propertyName) const;
};

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    std::size_t dataOffset = 0; // first byte after the end_header line
    std::size_t dataLine = 0;   // line number of that byte (ASCII messages)

    const PlyElement* find(std::string_view elementName) const;
};

// Parses the header at the start of `bytes`; throws InputError "<source>:<line>: ..." when it is
// malformed (no "ply" magic, no format or end_header line, unknown types, ...).
PlyHeader parsePlyHeader(std::string_view bytes, std::string_view source);

} // namespace vl::meshio
