#pragma once
// What the document tests start from and how they read a refusal.
#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/document/Document.h"

#include <filesystem>
#include <functional>
#include <string>
#include <unistd.h>

namespace vl::test {

// The bundled face (resolution 12) with its generated visemes (embedded geometry).
inline Document faceDocument() {
    Document document;
    document.face = makeFaceModel(face::Individual::Bundled, 12);
    return edit::generateVisemesFromFace(document);
}

// The InputError message of `edit`, or "(not refused)" when it did not throw.
inline std::string refusal(const std::function<void()>& edit) {
    try {
        edit();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(not refused)";
}

// An empty folder under the system's temporary directory (the process id keeps parallel runs apart).
inline std::filesystem::path tempDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("visemelab-document-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

} // namespace vl::test
