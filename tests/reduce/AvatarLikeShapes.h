#pragma once
// A deterministic stand-in for an avatar's 40 morph targets (issue 33's "real avatar's 40-target set":
// a Ready Player Me avatar carries ARKit-style blendshapes, which are not available here). Unlike
// randomInstance (every vertex moves in every shape) and rigInstance (a few muscles shared by all
// shapes), each target moves one small region of the face and leaves every other vertex exactly where
// it is, as exported blendshapes do: jaw, mouth, eyes, brows, cheeks and nose, mostly in left/right
// pairs with disjoint supports, with magnitudes from 1.5 mm (lip press) to 12 mm (jaw open).
#include "tests/reduce/RandomShapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace vl::test {

// One target: a displacement `direction * millimetres` at the region centre (x, y) in metres, falling
// off smoothly to exactly 0 at `radius` ((1 - (d/r)^2)^2); `mirrored` adds the same region mirrored in
// x (a bilateral target such as cheekPuff), with the direction's x mirrored too.
struct AvatarTargetSpec {
    double x, y, radius;
    Vec3 direction;
    double millimetres;
    bool mirrored = false;
};

// The ARKit-style targets; left ones at x < 0, each left/right pair listed once (`pair`: also right).
inline std::vector<AvatarTargetSpec> avatarTargetSpecs() {
    struct Entry {
        AvatarTargetSpec spec;
        bool pair;
    };
    const std::array<Entry, 26> entries{{
        {{0.0, -0.09, 0.06, Vec3(0, -1, -0.3), 12}, false},         // jawOpen
        {{0.0, -0.09, 0.06, Vec3(0, 0, 1), 4}, false},              // jawForward
        {{0.0, -0.09, 0.06, Vec3(-1, 0, 0), 4}, true},              // jawLeft / jawRight
        {{0.0, -0.05, 0.02, Vec3(0, 1, 0), 3}, false},              // mouthClose
        {{0.0, -0.045, 0.025, Vec3(0, 0, 1), 5}, false},            // mouthFunnel
        {{0.0, -0.045, 0.02, Vec3(0, 0.2, 1), 6}, false},           // mouthPucker
        {{0.0, -0.045, 0.03, Vec3(-1, 0, 0), 4}, true},             // mouthLeft / mouthRight
        {{-0.025, -0.045, 0.02, Vec3(-0.7, 0.7, 0), 6}, true},      // mouthSmile_L / _R
        {{-0.025, -0.05, 0.02, Vec3(0, -1, 0), 4}, true},           // mouthFrown_L / _R
        {{-0.03, -0.045, 0.015, Vec3(0, 0, -1), 2}, true},          // mouthDimple_L / _R
        {{-0.025, -0.05, 0.02, Vec3(-1, -0.3, 0), 4}, true},        // mouthStretch_L / _R
        {{0.0, -0.055, 0.015, Vec3(0, 0, -1), 3}, false},           // mouthRollLower
        {{0.0, -0.038, 0.015, Vec3(0, 0, -1), 3}, false},           // mouthRollUpper
        {{0.0, -0.06, 0.02, Vec3(0, 1, 0.3), 3}, false},            // mouthShrugLower
        {{0.0, -0.035, 0.02, Vec3(0, 1, 0), 2}, false},             // mouthShrugUpper
        {{-0.015, -0.045, 0.012, Vec3(0, 0, -1), 1.5}, true},       // mouthPress_L / _R
        {{-0.012, -0.055, 0.015, Vec3(0, -1, 0), 4}, true},         // mouthLowerDown_L / _R
        {{-0.012, -0.036, 0.015, Vec3(0, 1, 0), 4}, true},          // mouthUpperUp_L / _R
        {{-0.035, 0.035, 0.015, Vec3(0, -1, 0), 8}, true},          // eyeBlink_L / _R
        {{-0.035, 0.028, 0.018, Vec3(0, 1, 0), 2}, true},           // eyeSquint_L / _R
        {{-0.035, 0.04, 0.015, Vec3(0, 1, 0), 3}, true},            // eyeWide_L / _R
        {{-0.035, 0.06, 0.02, Vec3(0, -1, 0), 4}, true},            // browDown_L / _R
        {{0.0, 0.06, 0.02, Vec3(0, 1, 0), 5}, false},               // browInnerUp
        {{-0.05, 0.06, 0.018, Vec3(0, 1, 0), 4}, true},             // browOuterUp_L / _R
        {{-0.045, -0.02, 0.025, Vec3(-1, 0, 0.5), 5, true}, false}, // cheekPuff (both cheeks)
        {{-0.012, 0.0, 0.012, Vec3(0, 1, 0.3), 3}, false},          // noseSneer (one side: 40 targets)
    }};
    std::vector<AvatarTargetSpec> specs;
    for (const Entry& e : entries) {
        specs.push_back(e.spec);
        if (e.pair) {
            AvatarTargetSpec right = e.spec;
            right.x = -right.x;
            right.direction[0] = -right.direction[0];
            specs.push_back(right);
        }
    }
    return specs; // 40 targets
}

// `vertices` points on the front of a face-sized ellipsoid (metres), the 40 targets above as shapes,
// frequencies in [0.2, 1] and unit weights, all from `seed`.
inline RandomInstance avatarLikeInstance(unsigned seed, int vertices) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1), f(0.2, 1);
    constexpr double kHalfWidth = 0.08, kHalfHeight = 0.12, kDepth = 0.1;
    std::vector<Vec3> base;
    while (static_cast<int>(base.size()) < vertices) {
        const double x = unit(rng), y = unit(rng);
        if (x * x + y * y >= 1) continue;
        base.emplace_back(x * kHalfWidth, y * kHalfHeight, kDepth * std::sqrt(1 - x * x - y * y));
    }
    RandomInstance inst;
    for (const AvatarTargetSpec& spec : avatarTargetSpecs()) {
        std::vector<Vec3> shape = base;
        const Vec3 move = spec.direction.normalized() * (spec.millimetres * 1e-3);
        for (std::size_t k = 0; k < base.size(); ++k)
            for (const double side : {1.0, -1.0}) {
                if (side < 0 && !spec.mirrored) continue;
                const double dx = base[k][0] - side * spec.x, dy = base[k][1] - spec.y;
                const double q = (dx * dx + dy * dy) / (spec.radius * spec.radius);
                if (q >= 1) continue; // outside the region: exactly the neutral
                const double falloff = (1 - q) * (1 - q);
                shape[k] += Vec3(side * move[0], move[1], move[2]) * falloff;
            }
        inst.shapes.push_back(std::move(shape));
        inst.frequencies.push_back(f(rng));
    }
    inst.weights.assign(base.size(), 1.0);
    return inst;
}

} // namespace vl::test
