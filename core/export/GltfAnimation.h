#pragma once
// A glTF animation of a face's morph target weights (one "weights" channel on the face's node):
// what formatGlb adds to the exported face so that any glTF viewer plays the speech.
#include <string>
#include <vector>

namespace vl {

struct GltfMorphAnimation {
    enum class Interpolation { Linear, CubicSpline }; // glTF sampler interpolations
    std::string name = "speech";
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times; // seconds, strictly increasing
    // Per time: one weight per morph target (Linear), or in-tangents, values and out-tangents
    // (CubicSpline, 3 * targets; tangents are d(weight)/d(seconds), as glTF defines them).
    std::vector<float> values;
};

} // namespace vl
