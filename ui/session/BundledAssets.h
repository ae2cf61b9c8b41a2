#pragma once
// The bundled assets the editor reads and never writes (sample, phoneme tables and maps).
#include <filesystem>

namespace vl::ui {

// $VISEMELAB_ASSETS when set, else the assets folder the editor was built with.
std::filesystem::path assetsDirectory();
// True when `file` lies inside assetsDirectory().
bool isBundled(const std::filesystem::path& file);

} // namespace vl::ui
