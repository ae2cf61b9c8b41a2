#include "core/gltf/GlbContainer.h"

#include "core/common/Error.h"

#include <cstdint>

namespace vl {
namespace {

constexpr std::uint32_t kMagic = 0x46546C67;     // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;  // "BIN\0"

std::uint32_t readU32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int b = 3; b >= 0; --b)
        v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(b)]);
    return v;
}

void appendU32(std::string& out, std::uint32_t v) {
    for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xFF));
}

} // namespace

bool isGlb(std::string_view bytes) {
    return bytes.size() >= 4 && readU32(bytes, 0) == kMagic;
}

GlbChunks splitGlb(std::string_view bytes, std::string_view source) {
    const std::string where = std::string(source) + ": GLB";
    if (bytes.size() < 20) throwInputError(where, "file too short for a GLB header and chunk");
    if (readU32(bytes, 0) != kMagic) throwInputError(where, "not a binary glTF file (magic)");
    const std::uint32_t version = readU32(bytes, 4);
    if (version != 2) throwInputError(where, "container version " + std::to_string(version) + ", expected 2");
    const std::uint32_t length = readU32(bytes, 8);
    if (length > bytes.size())
        throwInputError(where, "header declares " + std::to_string(length) + " bytes, the file has " +
                                   std::to_string(bytes.size()));
    const std::string_view file = bytes.substr(0, length);
    GlbChunks chunks;
    std::size_t at = 12;
    for (int index = 0; at < file.size(); ++index) {
        const std::string chunkWhere = where + " chunk " + std::to_string(index);
        if (file.size() - at < 8) throwInputError(chunkWhere, "truncated chunk header");
        const std::uint32_t chunkLength = readU32(file, at), type = readU32(file, at + 4);
        at += 8;
        if (chunkLength > file.size() - at)
            throwInputError(chunkWhere, "declares " + std::to_string(chunkLength) + " bytes, " +
                                            std::to_string(file.size() - at) + " remain");
        const std::string_view data = file.substr(at, chunkLength);
        at += chunkLength;
        if (index == 0) {
            if (type != kChunkJson) throwInputError(chunkWhere, "the first chunk must be JSON");
            chunks.json = data;
        } else if (index == 1 && type == kChunkBin) {
            chunks.bin = data;
            chunks.hasBin = true;
        } else if (type == kChunkJson || type == kChunkBin) {
            throwInputError(chunkWhere, "a second JSON or BIN chunk");
        }
    }
    if (chunks.json.empty()) throwInputError(where, "empty JSON chunk");
    return chunks;
}

std::string joinGlb(std::string_view json, std::string_view bin) {
    const std::size_t jsonPadded = (json.size() + 3) & ~std::size_t{3};
    const std::size_t binPadded = (bin.size() + 3) & ~std::size_t{3};
    const std::size_t total = 12 + 8 + jsonPadded + (bin.empty() ? 0 : 8 + binPadded);
    if (total > 0xFFFFFFFFu) throwInputError("GLB", "the file would exceed 4 GB");
    std::string out;
    out.reserve(total);
    appendU32(out, kMagic);
    appendU32(out, 2);
    appendU32(out, static_cast<std::uint32_t>(total));
    appendU32(out, static_cast<std::uint32_t>(jsonPadded));
    appendU32(out, kChunkJson);
    out.append(json);
    out.append(jsonPadded - json.size(), ' ');
    if (!bin.empty()) {
        appendU32(out, static_cast<std::uint32_t>(binPadded));
        appendU32(out, kChunkBin);
        out.append(bin);
        out.append(binPadded - bin.size(), '\0');
    }
    return out;
}

} // namespace vl
