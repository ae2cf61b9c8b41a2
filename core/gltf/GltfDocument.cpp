#include "core/gltf/GltfDocument.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/InputRegistry.h"
#include "core/common/JsonParse.h"
#include "core/common/Limits.h"
#include "core/gltf/GlbContainer.h"

#include <cctype>
#include <fstream>

namespace vl {
namespace {

// tinygltf never touches the file system: buffers and images are VisemeLab's business.
bool denyFileExists(const std::string&, void*) {
    return false;
}
std::string keepPath(const std::string& path, void*) {
    return path;
}
bool denyRead(std::vector<unsigned char>*, std::string* error, const std::string&, void*) {
    if (error) *error = "file access is not tinygltf's";
    return false;
}
bool denyWrite(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    if (error) *error = "file access is not tinygltf's";
    return false;
}
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int,
               void*) {
    return true;
}

std::string percentDecode(std::string_view text, const GltfDocument& doc, std::string_view element) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '%') {
            out.push_back(text[i]);
            continue;
        }
        auto hex = [](char c) {
            return c >= '0' && c <= '9'   ? c - '0'
                   : c >= 'a' && c <= 'f' ? c - 'a' + 10
                   : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                          : -1;
        };
        if (i + 2 >= text.size() || hex(text[i + 1]) < 0 || hex(text[i + 2]) < 0)
            doc.fail(element, "malformed percent-escape in the URI");
        out.push_back(static_cast<char>(hex(text[i + 1]) * 16 + hex(text[i + 2])));
        i += 2;
    }
    return out;
}

// A scheme ("http:", "file:", "C:") makes a URI absolute or remote.
bool hasScheme(std::string_view uri) {
    const std::size_t colon = uri.find(':');
    if (colon == std::string_view::npos || colon == 0) return false;
    for (std::size_t i = 0; i < colon; ++i) {
        const char c = uri[i];
        const bool ok =
            std::isalpha(static_cast<unsigned char>(c)) ||
            (i > 0 && (std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.'));
        if (!ok) return false;
    }
    return true;
}

bool inside(const std::filesystem::path& folder, const std::filesystem::path& file) {
    auto f = folder.begin();
    auto p = file.begin();
    for (; f != folder.end(); ++f, ++p)
        if (p == file.end() || *p != *f) return false;
    return p != file.end();
}

bool usesExtension(const nlohmann::ordered_json& json, std::string_view name) {
    const auto it = json.find("extensionsUsed");
    if (it == json.end() || !it->is_array()) return false;
    for (const auto& e : *it)
        if (e.is_string() && e.get<std::string>() == name) return true;
    return false;
}

void loadBuffers(GltfDocument& doc, const std::shared_ptr<const std::string>& file, const GlbChunks* glb) {
    const auto it = doc.json.find("buffers");
    if (it == doc.json.end()) return;
    if (!it->is_array()) doc.fail("buffers", "not an array");
    const bool meshopt = usesExtension(doc.json, "EXT_meshopt_compression");
    for (std::size_t i = 0; i < it->size(); ++i) {
        const std::string element = "buffers/" + std::to_string(i);
        const auto& b = (*it)[i];
        if (!b.is_object()) doc.fail(element, "not an object");
        const auto length = b.find("byteLength");
        if (length == b.end() || !length->is_number_unsigned() || length->get<std::uint64_t>() == 0)
            doc.fail(element, "byteLength must be an integer >= 1");
        const std::uint64_t byteLength = length->get<std::uint64_t>();
        GltfBuffer buffer;
        const auto uri = b.find("uri");
        if (uri != b.end() && !uri->is_string()) doc.fail(element + "/uri", "not a string");
        buffer.uri = uri != b.end() ? uri->get<std::string>() : "";
        if (buffer.uri.empty()) {
            const bool fallback = b.contains("extensions") && b["extensions"].is_object() &&
                                  b["extensions"].contains("EXT_meshopt_compression");
            if (glb && i == 0 && !fallback) {
                if (!glb->hasBin) doc.fail(element, "refers to the GLB BIN chunk, but the file has none");
                if (byteLength > glb->bin.size())
                    doc.fail(element, "byteLength " + std::to_string(byteLength) +
                                          " exceeds the BIN chunk (" + std::to_string(glb->bin.size()) +
                                          " bytes)");
                buffer.storage = file;
                buffer.offset = static_cast<std::size_t>(glb->bin.data() - file->data());
            } else if (fallback || meshopt) {
                buffer.placeholder = true;
                buffer.storage = std::make_shared<const std::string>();
                doc.buffers.push_back(std::move(buffer));
                continue;
            } else {
                doc.fail(element, "has no uri and is not the GLB BIN chunk");
            }
        } else if (isDataUri(buffer.uri)) {
            std::vector<unsigned char> decoded;
            std::string mime;
            if (!tinygltf::DecodeDataURI(&decoded, mime, buffer.uri, 0, false))
                doc.fail(element + "/uri", "not a base64 data URI of type application/octet-stream or "
                                           "application/gltf-buffer");
            if (decoded.size() < byteLength)
                doc.fail(element, "byteLength " + std::to_string(byteLength) + " exceeds the " +
                                      std::to_string(decoded.size()) + " bytes of its data URI");
            buffer.storage = std::make_shared<const std::string>(decoded.begin(), decoded.end());
        } else {
            std::string bytes = doc.readExternal(buffer.uri, element + "/uri", byteLength);
            if (bytes.size() < byteLength)
                doc.fail(element, "byteLength " + std::to_string(byteLength) + " exceeds the " +
                                      std::to_string(bytes.size()) + " bytes of '" + buffer.uri + "'");
            buffer.storage = std::make_shared<const std::string>(std::move(bytes));
        }
        buffer.length = static_cast<std::size_t>(byteLength);
        doc.buffers.push_back(std::move(buffer));
    }
}

// The JSON tinygltf parses: buffers replaced by tiny data URIs and images by names of files it is
// not allowed to open, so it allocates nothing the file declares and opens nothing.
std::string tinygltfView(const nlohmann::ordered_json& json) {
    nlohmann::ordered_json copy = json;
    if (copy.contains("buffers") && copy["buffers"].is_array())
        for (auto& b : copy["buffers"])
            b = {{"byteLength", 4}, {"uri", "data:application/octet-stream;base64,AAAAAA=="}};
    if (copy.contains("images") && copy["images"].is_array())
        for (auto& image : copy["images"]) image = {{"uri", "not-loaded-by-tinygltf"}};
    // Draco primitives have index accessors without a buffer view, which tinygltf 2.7 refuses;
    // their indices come from the Draco stream (core/gltf/DracoDecode).
    if (copy.contains("meshes") && copy["meshes"].is_array())
        for (auto& mesh : copy["meshes"]) {
            if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
            for (auto& p : mesh["primitives"])
                if (p.is_object() && p.contains("extensions") && p["extensions"].is_object() &&
                    p["extensions"].contains("KHR_draco_mesh_compression"))
                    p.erase("indices");
        }
    return copy.dump();
}

} // namespace

bool isDataUri(std::string_view uri) {
    return uri.substr(0, 5) == "data:";
}

void GltfDocument::fail(std::string_view element, std::string_view what) const {
    throwInputError(source + (element.empty() ? "" : ": " + std::string(element)), what);
}

std::string GltfDocument::readExternal(const std::string& uri, std::string_view element,
                                       std::size_t maxBytes) const {
    const std::string name = percentDecode(uri, *this, element);
    const std::string quoted = "'" + uri + "'";
    if (folder.empty())
        fail(element, "external file " + quoted + " refused: the document was not read from a file");
    if (name.empty() || name.find('\0') != std::string::npos)
        fail(element, "empty or malformed URI " + quoted);
    if (name.front() == '/' || name.find('\\') != std::string::npos || hasScheme(name))
        fail(element, "URI " + quoted + " is absolute or remote; only files beside the glTF file are read");
    const std::filesystem::path relative(name);
    for (const auto& part : relative)
        if (part == "..") fail(element, "URI " + quoted + " leads outside the glTF file's folder");
    std::error_code ec;
    const std::filesystem::path base = std::filesystem::weakly_canonical(folder, ec);
    const std::filesystem::path path = std::filesystem::canonical(folder / relative, ec);
    if (ec) fail(element, "file " + quoted + " not found beside " + source);
    if (!std::filesystem::is_regular_file(path, ec))
        fail(element, "URI " + quoted + " is not a regular file");
    if (!inside(base, path))
        fail(element, "URI " + quoted + " leads outside the glTF file's folder (symlink)");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) fail(element, "cannot read " + quoted);
    if (std::min<std::uintmax_t>(size, maxBytes) > limits::kMaxInputFileBytes)
        fail(element,
             quoted + " is larger than " + std::to_string(limits::kMaxInputFileBytes >> 20) + " MiB");
    const std::size_t wanted = std::min<std::uintmax_t>(size, maxBytes);
    std::string bytes(wanted, '\0');
    std::ifstream in(path, std::ios::binary);
    if (!in.read(bytes.data(), static_cast<std::streamsize>(wanted))) fail(element, "cannot read " + quoted);
    noteInputFile(path, bytes); // an output of the run may not overwrite a buffer it read
    return bytes;
}

GltfDocument parseGltfDocument(std::string bytes, std::string_view source,
                               const std::filesystem::path& folder) {
    GltfDocument doc;
    doc.source = std::string(source);
    doc.folder = folder;
    const auto file = std::make_shared<const std::string>(std::move(bytes));
    GlbChunks chunks;
    std::string_view jsonText = *file;
    doc.binary = isGlb(*file);
    if (doc.binary) {
        chunks = splitGlb(*file, source);
        jsonText = chunks.json;
    }
    doc.json = parseJsonStrict(jsonText, source); // nesting limited before any parser recurses
    if (!doc.json.is_object()) doc.fail("", "the JSON document is not an object");
    if (!doc.json.contains("asset") || !doc.json["asset"].is_object() ||
        !doc.json["asset"].contains("version"))
        doc.fail("asset", "missing asset.version (not a glTF file)");
    const auto& version = doc.json["asset"]["version"];
    if (!version.is_string() || version.get<std::string>().substr(0, 2) != "2.")
        doc.fail("asset/version", "only glTF 2.x is supported");
    loadBuffers(doc, file, doc.binary ? &chunks : nullptr);

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skipImage, nullptr);
    loader.SetFsCallbacks({&denyFileExists, &keepPath, &denyRead, &denyWrite, nullptr});
    std::string error, warning;
    const std::string view = tinygltfView(doc.json);
    if (!loader.LoadASCIIFromString(&doc.model, &error, &warning, view.data(),
                                    static_cast<unsigned int>(view.size()), ""))
        doc.fail("", "not a readable glTF file: " + (error.empty() ? warning : error));
    return doc;
}

GltfDocument loadGltfDocument(const std::filesystem::path& path) {
    return parseGltfDocument(readFileToString(path), path.string(),
                             path.parent_path().empty() ? "." : path.parent_path());
}

} // namespace vl
