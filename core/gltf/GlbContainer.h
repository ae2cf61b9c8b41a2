#pragma once
// The binary glTF container (glTF 2.0 spec, section 4.4 "GLB File Format Specification"): a
// 12-byte header (magic "glTF", version 2, total length), a JSON chunk, and an optional BIN chunk.
// Every length is checked against the bytes present before anything is used.
#include <string>
#include <string_view>

namespace vl {

struct GlbChunks {
    std::string_view json;
    std::string_view bin; // empty when the file has no BIN chunk
    bool hasBin = false;
};

// True when `bytes` start with the GLB magic.
bool isGlb(std::string_view bytes);

// Splits a GLB file; throws InputError naming `source` and the header field or chunk at fault.
// Chunks after BIN (allowed by the spec, of unknown type) are skipped.
GlbChunks splitGlb(std::string_view bytes, std::string_view source);

// A GLB file from a JSON text and binary payload: the JSON padded with spaces and the BIN chunk
// with zeros to 4 bytes; no BIN chunk when `bin` is empty.
std::string joinGlb(std::string_view json, std::string_view bin);

} // namespace vl
