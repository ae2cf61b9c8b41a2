#include "core/common/FileNames.h"

#include <cctype>

namespace vl {

std::string fileSafeName(std::string_view name) {
    std::string safe(name);
    for (char& c : safe)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '+') c = '_';
    return safe;
}

} // namespace vl
