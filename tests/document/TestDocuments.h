#pragma once
// Documents and folders the document tests start from.
#include "core/document/Commands.h"
#include "core/document/Document.h"

#include <filesystem>
#include <string>

namespace vl::test {

// A face document with its generated visemes (embedded geometry).
inline Document faceDocument() {
    Document document;
    document.face = makeFaceModel(face::Individual::Bundled, 12);
    return edit::generateVisemesFromFace(document);
}

// An empty folder under the system's temporary directory.
inline std::filesystem::path tempDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("visemelab-document-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace vl::test
