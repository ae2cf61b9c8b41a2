#include "ui/session/BundledAssets.h"

#include <cstdlib>

namespace vl::ui {

std::filesystem::path assetsDirectory() {
    if (const char* env = std::getenv("VISEMELAB_ASSETS"); env && *env) return env;
    return VISEMELAB_ASSETS_DIR;
}

bool isBundled(const std::filesystem::path& file) {
    std::error_code error;
    const auto assets = std::filesystem::weakly_canonical(assetsDirectory(), error);
    const auto canonical = std::filesystem::weakly_canonical(file, error);
    if (error) return false;
    const auto relative = canonical.lexically_relative(assets);
    return !relative.empty() && *relative.begin() != "..";
}

} // namespace vl::ui
