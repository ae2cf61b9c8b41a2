#include "core/common/Error.h"

namespace vl {

void throwInputError(std::string_view where, std::string_view what) {
    std::string message(where);
    message += ": ";
    message += what;
    throw InputError(message);
}

std::string fileLine(std::string_view file, std::size_t line) {
    return std::string(file) + ":" + std::to_string(line);
}

} // namespace vl
