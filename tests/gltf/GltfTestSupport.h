#pragma once
// Helpers of the core/gltf tests: parse fixtures from memory, edit a GLB's JSON, and check that an
// error names what it should.
#include "core/common/Error.h"
#include "core/gltf/AvatarScan.h"
#include "core/gltf/GlbContainer.h"
#include "core/gltf/GltfDocument.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace vl::test {

inline AvatarScan scanGlb(const std::string& glb, const std::string& pattern = "",
                          const std::filesystem::path& folder = {}) {
    return scanAvatar(parseGltfDocument(glb, "avatar.glb", folder), {pattern});
}

// The GLB with its JSON edited by `edit` (the BIN chunk unchanged).
inline std::string editGlb(const std::string& glb, const std::function<void(nlohmann::ordered_json&)>& edit) {
    const GlbChunks chunks = splitGlb(glb, "fixture");
    nlohmann::ordered_json json = nlohmann::ordered_json::parse(chunks.json);
    edit(json);
    return joinGlb(json.dump(), chunks.bin);
}

inline nlohmann::ordered_json glbJson(const std::string& glb) {
    return nlohmann::ordered_json::parse(splitGlb(glb, "fixture").json);
}

// Runs `f`, expects an InputError whose message contains every string of `parts`.
inline void expectInputError(const std::function<void()>& f, const std::vector<std::string>& parts) {
    try {
        f();
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        for (const std::string& part : parts)
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos)
                << "'" << part << "' not in: " << e.what();
    }
}

} // namespace vl::test
