#pragma once
// The source of app/web/visemelab-player.js, embedded at build time (PlayerModule.cpp is generated
// by app/CMakeLists.txt), for the pages `visemelab say --html` writes.
#include <string_view>

namespace vl::cli {

std::string_view playerModuleSource();

} // namespace vl::cli
