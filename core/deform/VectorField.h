#pragma once
// Vector fields V: (u,v) -> R^3 on the normalised face domain [0,1]^2 (paper "Adaptive Deformable
// Models", section 3.2). Two kinds, both plain editable data that the project file saves:
// - SampledField: a grid of vectors with bilinear lookup, clamped at the border (a geometry image);
// - InfluenceField: an analytic elliptic influence region with a monotone falloff, zero outside.
// A VectorField is the sum of an optional sampled part and any number of influence regions, which is
// how composite fields (the jaw's constant chin area plus its lip opening) are described.
#include "core/common/EnumNames.h"
#include "core/mesh/Mesh.h"

#include <string_view>
#include <vector>

namespace vl {

// Sample (i, j) sits at u = i / (width - 1), v = j / (height - 1) (0 when the size is 1).
// Samples are row-major: samples[j * width + i]. An empty grid (0 x 0) is the zero field.
struct SampledField {
    int width = 0;
    int height = 0;
    std::vector<Vec3> samples;

    bool empty() const { return samples.empty(); }
    const Vec3& sample(int i, int j) const { return samples[static_cast<std::size_t>(j) * width + i]; }
    // Bilinear interpolation; (u,v) outside [0,1]^2 is clamped to the border.
    Vec3 at(double u, double v) const;
    bool operator==(const SampledField&) const = default;
};

// How an influence decreases from 1 (inner plateau) to 0 (outer ellipse); all are monotone and
// reach exactly 0 at the border, so the field is continuous.
enum class Falloff { Linear, Smoothstep, Cosine, Gaussian };
template <> struct EnumNames<Falloff> {
    static constexpr const char* what = "falloff";
    static constexpr EnumName<Falloff> names[] = {{Falloff::Linear, "linear"},
                                                  {Falloff::Smoothstep, "smoothstep"},
                                                  {Falloff::Cosine, "cosine"},
                                                  {Falloff::Gaussian, "gaussian"}};
};

// Falloff value for t in [0,1] (t <= 0 gives 1, t >= 1 gives 0).
double falloffWeight(Falloff kind, double t);

// An elliptic influence region. Inside the inner "plateau" ellipse the field is the full
// magnitude * normalised(direction); between the plateau and the outer ellipse it decreases
// monotonically along each ray from the centre; outside the outer ellipse it is zero.
struct InfluenceField {
    Vec2 centre{0.5, 0.5};
    Vec2 radii{0.1, 0.1};          // outer semi-axes along the (rotated) u and v axes, > 0
    Vec2 plateau{0.0, 0.0};        // inner semi-axes: both 0 (no plateau) or both in (0, radii)
    double rotation = 0.0;         // radians, counter-clockwise in (u,v)
    Vec3 direction{0.0, 0.0, 1.0}; // non-zero; only its direction matters
    double magnitude = 1.0;        // length of the vector on the plateau (may be negative)
    Falloff falloff = Falloff::Smoothstep;

    // Scalar weight in [0,1] at (u,v).
    double weight(double u, double v) const;
    Vec3 at(double u, double v) const;
    bool operator==(const InfluenceField&) const = default;
};

struct VectorField {
    SampledField sampled;                   // empty = contributes nothing
    std::vector<InfluenceField> influences; // summed

    Vec3 at(double u, double v) const;
    bool isZero() const { return sampled.empty() && influences.empty(); }
    bool operator==(const VectorField&) const = default;
};

// Throws InputError "<where>: ..." naming the offending element (grid size, region index, radii,
// plateau, direction, non-finite numbers).
void validateField(const VectorField& field, std::string_view where);

// Samples `f(u,v)` on a width x height grid (the way geometry images are made from analytic shapes).
template <class F> SampledField sampleGrid(int width, int height, F&& f) {
    SampledField grid;
    grid.width = width;
    grid.height = height;
    grid.samples.reserve(static_cast<std::size_t>(width) * height);
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            grid.samples.push_back(
                f(width > 1 ? double(i) / (width - 1) : 0.0, height > 1 ? double(j) / (height - 1) : 0.0));
    return grid;
}

} // namespace vl
