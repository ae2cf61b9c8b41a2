#pragma once
// The InputError message a call throws, or "no error": tests compare messages users will read.
#include "core/common/Error.h"

#include <functional>
#include <string>

namespace vl::test {

inline std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

} // namespace vl::test
