#pragma once
// What every loader's libFuzzer target checks (docs/robustness.md): arbitrary bytes end either in a
// loaded value that keeps its invariants or in an InputError whose message names the file. Anything
// else escaping a loader (std::out_of_range, a JSON library exception, bad_alloc ...) is a bug: the
// CLI would answer it with "internal error" (exit 1). The target aborts so libFuzzer reports it with
// the input that caused it. Crashes, leaks, UB, timeouts and oversized allocations are caught by
// libFuzzer and the sanitizers themselves.
#include "core/common/Error.h"
#include "core/mesh/Mesh.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace vl::fuzz {

// Stops the run with a message (shown in libFuzzer's crash report).
[[noreturn]] void fail(std::string_view what);

// Runs `load`; an InputError must name `source`, any other exception fails.
template <class Load> void expectLoadedOrDataError(std::string_view source, Load&& load) {
    try {
        load();
    } catch (const InputError& e) {
        if (std::string_view(e.what()).find(source) == std::string_view::npos)
            fail(std::string("InputError does not name the file ") + std::string(source) + ": " + e.what());
    }
}

// A loaded mesh: at least one triangle, indices in range, finite coordinates, one (u,v) per vertex
// or none.
void checkMesh(const MeshData& mesh);

// The input as text (libFuzzer hands out bytes).
inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// An empty folder private to this process, emptied again on every call (removed at exit): a loader
// that reads files beside its input sees only what the current input wrote.
std::filesystem::path freshInputFolder();
// Writes `bytes` into `file`; fails the run when it cannot.
void writeFile(const std::filesystem::path& file, std::string_view bytes);

// For loaders that only read paths: writes the input into `name` inside a folder private to this
// process (freshInputFolder) and returns its path.
std::filesystem::path writeInputFile(std::string_view name, const std::uint8_t* data, std::size_t size);

// True when the text's first non-blank character opens a JSON value: targets of loaders that read
// JSON or a line format by extension use it to pick the extension, so mutations reach both readers.
bool looksLikeJson(std::string_view text);

} // namespace vl::fuzz
