#pragma once
// The message of the InputError a call throws ("" when it throws none), for tests of error texts.
#include "core/common/Error.h"

#include <functional>
#include <string>

namespace vl::test {

inline std::string errorOf(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

} // namespace vl::test
