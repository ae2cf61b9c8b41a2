#include "core/inspect/VertexErrors.h"

#include "core/common/Error.h"

#include <string>

namespace vl {

std::vector<double> vertexErrors(std::span<const Vec3> a, std::span<const Vec3> b,
                                 std::span<const double> weights) {
    if (a.size() != b.size() || a.size() != weights.size())
        throwInputError("vertex errors", "sizes differ: " + std::to_string(a.size()) + ", " +
                                             std::to_string(b.size()) + " and " +
                                             std::to_string(weights.size()) + " weights");
    std::vector<double> errors(a.size());
    for (std::size_t k = 0; k < a.size(); ++k) errors[k] = weights[k] * (a[k] - b[k]).sqrnorm();
    return errors;
}

} // namespace vl
