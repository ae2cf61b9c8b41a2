#pragma once
// A glTF 2.0 file (.glb, .gltf, .vrm) as VisemeLab reads it: the JSON document exactly as written
// (the template the avatar writer edits, so whatever VisemeLab does not touch survives), tinygltf's
// typed parse of the same document, and the bytes of every buffer.
//
// Reading is hardened against hostile files before any parser or allocation sees them:
// - JSON nesting is limited (limits::kMaxJsonDepth) by a scan before nlohmann or tinygltf parse
//   it (tinygltf recurses per level of extras), duplicate keys and 1e999 refused (core/common/JsonParse);
// - GLB header and chunk lengths are checked against the bytes present;
// - buffers are loaded by VisemeLab, not tinygltf: the GLB BIN chunk, base64 data URIs, or files
//   whose URI is relative and stays inside the glTF file's folder (no absolute paths, no "..", no
//   directories, no symlink leading out); a declared byteLength larger than the bytes present is
//   an error, never an allocation;
// - an EXT_meshopt_compression fallback buffer without data is recorded as a placeholder.
// tinygltf parses a copy of the JSON whose buffers and images are stubbed, so it never opens a
// file or decodes a large data URI itself.
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

struct GltfBuffer {
    std::shared_ptr<const std::string> storage; // owns the bytes (file, BIN chunk or decoded URI)
    std::size_t offset = 0, length = 0;         // the buffer's byteLength bytes within storage
    bool placeholder = false;                   // a fallback buffer without data (EXT_meshopt_compression)
    std::string uri;                            // as written; empty for the GLB BIN chunk

    const unsigned char* data() const {
        return reinterpret_cast<const unsigned char*>(storage->data()) + offset;
    }
};

class GltfDocument {
  public:
    std::string source;           // the file as named in messages
    std::filesystem::path folder; // where relative URIs resolve; empty: external files are refused
    bool binary = false;          // read from a GLB container
    nlohmann::ordered_json json;  // the document as written
    tinygltf::Model model;        // tinygltf's typed parse (buffers and images stubbed: use `buffers`)
    std::vector<GltfBuffer> buffers;

    // Throws InputError "<source>: <element>: <what>".
    [[noreturn]] void fail(std::string_view element, std::string_view what) const;

    // The bytes of a file named by a relative URI of this document (a buffer or image), confined to
    // `folder`; at most `maxBytes` are accepted. `element` names the referring JSON element.
    std::string readExternal(const std::string& uri, std::string_view element, std::size_t maxBytes) const;
};

// Parses `bytes` (GLB or JSON glTF, detected by the magic); `folder` resolves external URIs.
GltfDocument parseGltfDocument(std::string bytes, std::string_view source,
                               const std::filesystem::path& folder);
// Reads a file and parses it; external URIs resolve beside it.
GltfDocument loadGltfDocument(const std::filesystem::path& path);

// True for a data URI ("data:...;base64,...").
bool isDataUri(std::string_view uri);

} // namespace vl
