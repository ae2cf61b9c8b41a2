// Preview colours of the bundled faces: skin with lips, eyes, brows and nostrils tinted, so
// renders read as a face at a glance.
#include "core/deform/FaceShape.h"

namespace vl::face {

std::vector<Vec3> faceColours(std::span<const Vec2> uvs) {
    using namespace detail;
    const Vec3 skin(0.87, 0.71, 0.60), lip(0.70, 0.36, 0.36), white(0.95, 0.95, 0.93);
    const Vec3 iris(0.25, 0.17, 0.1), brow(0.35, 0.24, 0.16), nostril(0.35, 0.2, 0.18);
    std::vector<Vec3> colours;
    colours.reserve(uvs.size());
    const auto mix = [](const Vec3& a, const Vec3& b, double t) { return a * (1.0 - t) + b * t; };
    for (const auto& uv : uvs) {
        const double u = uv[0], v = uv[1];
        Vec3 c = mix(skin, lip, lipWeight(u, v));
        c = mix(c, brow, browWeight(u, v));
        c = mix(c, nostril, nostrilWeight(u, v));
        c = mix(c, white, eyeWhiteWeight(u, v));
        c = mix(c, iris, 0.75 * irisWeight(u, v)); // soft: few vertices cover an iris
        colours.push_back(c);
    }
    return colours;
}

} // namespace vl::face
