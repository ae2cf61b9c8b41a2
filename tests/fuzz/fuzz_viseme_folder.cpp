// libFuzzer target: a viseme folder as `visemelab reduce --visemes DIR` and `project new` load it
// (core/io listVisemeFolder + loadVisemeSet): the neutral mesh and every other mesh file of the
// folder, each read by its extension's reader and checked to be interpolable with the neutral.
// An input is a small archive of the folder: lines "=== <file name>" start each file, e.g.
//   === neutral.obj
//   v 0 0 0 ...
//   === aa.ply
//   ply ...
#include "FuzzSupport.h"
#include "core/io/VisemeSetFiles.h"

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace {

constexpr std::string_view kFileMarker = "=== ";
constexpr std::size_t kMaxFiles = 16;

// A name that stays inside the folder: letters, digits, '.', '-', '_' only, not starting with '.'.
std::string folderFileName(std::string_view text) {
    std::string name;
    for (const char c : text.substr(0, 32))
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') name += c;
    while (!name.empty() && name.front() == '.') name.erase(name.begin());
    return name;
}

// The files of the archive; text before the first marker and files with an unusable name are dropped
// (a repeated name: the last one is written).
std::vector<std::pair<std::string, std::string_view>> unpack(std::string_view input) {
    std::vector<std::pair<std::string, std::string_view>> files;
    std::string name;
    std::size_t bodyStart = std::string_view::npos;
    const auto close = [&](std::size_t bodyEnd) {
        if (bodyStart != std::string_view::npos && !name.empty() && files.size() < kMaxFiles)
            files.emplace_back(name, input.substr(bodyStart, bodyEnd - bodyStart));
    };
    for (std::size_t line = 0; line < input.size();) {
        const std::size_t eol = std::min(input.find('\n', line), input.size());
        const std::size_t next = std::min(eol + 1, input.size());
        if (input.substr(line, eol - line).starts_with(kFileMarker)) {
            close(line);
            name = folderFileName(input.substr(line + kFileMarker.size(), eol - line - kFileMarker.size()));
            bodyStart = next;
        }
        line = next;
    }
    close(input.size());
    return files;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace fs = std::filesystem;
    const fs::path folder = vl::fuzz::freshInputFolder();
    for (const auto& [name, body] : unpack(vl::fuzz::asText(data, size)))
        vl::fuzz::writeFile(folder / name, body);
    // Like `reduce --visemes DIR` without --neutral: the first of neutral.obj/.ply/.wrl.
    fs::path neutral;
    for (const char* candidate : {"neutral.obj", "neutral.ply", "neutral.wrl"})
        if (neutral.empty() && fs::is_regular_file(folder / candidate)) neutral = folder / candidate;
    if (neutral.empty()) return 0;
    vl::fuzz::expectLoadedOrDataError(folder.string(), [&] {
        const vl::VisemeSet set = vl::loadVisemeSet(neutral, vl::listVisemeFolder(folder, neutral));
        vl::fuzz::checkMesh(set.neutral);
        if (set.size() < 2) vl::fuzz::fail("loaded a viseme set of fewer than 2 visemes");
        for (const vl::Viseme& viseme : set.visemes)
            if (viseme.positions.size() != set.vertexCount())
                vl::fuzz::fail("viseme not interpolable with the neutral");
    });
    return 0;
}
