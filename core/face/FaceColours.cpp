// Preview colours of the bundled head: skin with lips, brows, nostrils and the eye openings tinted;
// the other parts by their (u,v) tile (eyeballs with iris and pupil, teeth with gums, tongue, mouth
// cavity), so renders read as a face at a glance.
#include "core/face/FaceShape.h"

#include <algorithm>

namespace vl::face {

namespace {

Vec3 mix(const Vec3& a, const Vec3& b, double t) {
    return a * (1.0 - t) + b * t;
}

Vec3 skinColour(double u, double v) {
    using namespace detail;
    const Vec3 skin(0.87, 0.71, 0.60), lip(0.70, 0.36, 0.36), brow(0.35, 0.24, 0.16),
        nostril(0.35, 0.2, 0.18);
    const Vec3 socket(0.30, 0.15, 0.13), lash(0.22, 0.15, 0.12);
    Vec3 c = mix(skin, lip, lipWeight(u, v));
    c = mix(c, brow, browWeight(u, v));
    c = mix(c, nostril, nostrilWeight(u, v));
    const EyeLens lens = eyeLens(u, v);
    const double inside = lens.inside();
    if (inside > -0.6 && std::abs(lens.along) < 1.0) {
        // Lashes darken the upper lid's margin; the opening itself is the dark socket.
        if (lens.offset > 0.0) c = mix(c, lash, std::clamp(1.0 + inside / 0.6, 0.0, 1.0) * 0.8);
        c = mix(c, socket, std::clamp(inside / 0.15 + 1.0, 0.0, 1.0));
    }
    return c;
}

Vec3 eyeColour(double s, double t) {
    // t: angle from the front of the eyeball / pi; s: around it.
    (void)s;
    const Vec3 sclera(0.94, 0.93, 0.9), iris(0.33, 0.24, 0.14), pupil(0.05, 0.04, 0.04);
    if (t < 0.055) return pupil;
    if (t < 0.075) return mix(pupil, iris, (t - 0.055) / 0.02);
    if (t < 0.14) return mix(iris, iris * 0.6, std::clamp((t - 0.12) / 0.02, 0.0, 1.0)); // darker limbal ring
    if (t < 0.16) return mix(iris * 0.6, sclera, (t - 0.14) / 0.02);
    return sclera;
}

} // namespace

std::vector<Vec3> faceColours(std::span<const Vec2> uvs) {
    std::vector<Vec3> colours;
    colours.reserve(uvs.size());
    for (const auto& uv : uvs) {
        const double local = uv[0] - std::floor(uv[0]), t = std::clamp(uv[1], 0.0, 1.0);
        switch (headTileOf(uv[0])) {
        case HeadTile::Skin:
            colours.push_back(skinColour(uv[0], uv[1]));
            break;
        case HeadTile::Eye:
            colours.push_back(eyeColour(local, t));
            break;
        case HeadTile::Teeth: // t: 0 at the gum's root, the crown from about 0.2
            colours.push_back(
                mix(Vec3(0.82, 0.42, 0.43), Vec3(0.95, 0.93, 0.85), std::clamp((t - 0.15) / 0.08, 0.0, 1.0)));
            break;
        case HeadTile::Tongue: // t: 0 at the root, 1 at the tip
            colours.push_back(mix(Vec3(0.55, 0.22, 0.24), Vec3(0.86, 0.45, 0.45), std::clamp(t, 0.0, 1.0)));
            break;
        case HeadTile::Cavity: // t: 0 at the lips, 1 at the throat
            colours.push_back(
                mix(Vec3(0.55, 0.25, 0.25), Vec3(0.12, 0.04, 0.04), std::clamp(t * 1.5, 0.0, 1.0)));
            break;
        }
    }
    return colours;
}

} // namespace vl::face
