#pragma once
// Surface-contour error of a piecewise linear approximation (paper equations 5-7): at (u,v) inside a
// triangle, the distance between the surface point p(u,v) and the triangle's linear interpolation
// P(u,v) of its vertex positions. The integral over the triangle is approximated by the composite
// centroid rule: the triangle is cut into n x n equal sub-triangles (a barycentric grid) and the error
// is sampled at their centroids, so the average is the mean of the samples; the maximum is the largest
// sample.
#include "core/adaptive/Surface.h"

#include <array>
#include <vector>

namespace vl {

// Barycentric coordinates of the n*n sample points (n >= 1).
std::vector<Vec3> contourSamplePattern(int samplesPerSide);

struct TriangleError {
    double average = 0.0;
    double maximum = 0.0;
};

// Error of the triangle with corners at `uv` in the domain and `p` in space.
TriangleError triangleContourError(const Surface& surface, const std::array<Vec2, 3>& uv,
                                   const std::array<Vec3, 3>& p, const std::vector<Vec3>& pattern);

// triangleContourError(...).average > averageLimit || .maximum > maximumLimit, decided from as few
// samples as possible: the refinement test (the same answer to the bit; the sum only grows).
bool triangleContourErrorExceeds(const Surface& surface, const std::array<Vec2, 3>& uv,
                                 const std::array<Vec3, 3>& p, const std::vector<Vec3>& pattern,
                                 double averageLimit, double maximumLimit);

struct ContourErrorStats {
    double average = 0.0; // integral of the error over the domain / domain area (in (u,v))
    double maximum = 0.0;
    std::size_t samples = 0;
};

// Measured error of a whole mesh with (u,v) against the surface: per-triangle averages weighted by
// the triangle's (u,v) area, and the largest sample. Throws InputError for a mesh without (u,v).
ContourErrorStats measureContourError(const MeshData& mesh, const Surface& surface, int samplesPerSide = 8);

} // namespace vl
