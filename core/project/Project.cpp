#include "core/project/Project.h"

namespace vl {

int Project::findViseme(std::string_view name) const {
    for (std::size_t i = 0; i < visemes.size(); ++i)
        if (visemes[i].name == name) return static_cast<int>(i);
    return -1;
}

} // namespace vl
