#include "core/gltf/KeyTable.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace vl {

double writtenFrequency(double frequency) {
    if (!std::isfinite(frequency) || frequency == 0.0) return frequency;
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", frequency);
    return std::strtod(text, nullptr);
}

int impliedTarget(const std::string& name, const std::vector<std::string>& targetNames,
                  const std::vector<std::vector<std::string>>& members,
                  const std::vector<std::vector<int>>& keyTargets) {
    const auto named = std::find(targetNames.rbegin(), targetNames.rend(), name);
    if (named != targetNames.rend()) return static_cast<int>(targetNames.rend() - named) - 1;
    for (std::size_t k = 0; k < members.size() && k < keyTargets.size(); ++k)
        if (!keyTargets[k].empty() &&
            std::find(members[k].begin(), members[k].end(), name) != members[k].end())
            return keyTargets[k].front();
    return -1;
}

} // namespace vl
