#pragma once
// A thin-plate spline map R^2 -> R^2 (Bookstein 1989): the smoothest map (least bending energy) that
// takes each control point exactly to its target,
//   f(x) = a + A x + sum_i w_i phi(|x - c_i|),   phi(r) = r^2 log r,
// with the side conditions sum w_i = 0 and sum w_i c_i = 0 (so the affine part a + A x is the
// least-squares part of the map). With three control points it is the affine map through them.
#include "core/mesh/Mesh.h"

#include <span>
#include <vector>

namespace vl::face {

class ThinPlateSpline {
  public:
    ThinPlateSpline() = default;
    // Throws InputError when there are fewer than 3 points, the counts differ, or the control points
    // are (nearly) collinear or coincident.
    ThinPlateSpline(std::span<const Vec2> controls, std::span<const Vec2> targets);

    Vec2 operator()(const Vec2& x) const;
    // The Jacobian determinant of the map at x (central differences with step h).
    double jacobianDeterminant(const Vec2& x, double h = 1e-4) const;
    // The affine part: f_affine(x) = a + A x (A's rows are linear(0), linear(1)).
    Vec2 affine(const Vec2& x) const;

  private:
    std::vector<Vec2> controls_;
    std::vector<Vec2> weights_; // w_i, one 2D weight per control point
    Vec2 offset_{0, 0};
    Vec2 linearX_{1, 0}, linearY_{0, 1}; // columns of A: f_affine = offset + x * linearX + y * linearY
};

// Solves the dense linear system m x = b in place (Gaussian elimination with partial pivoting); m is
// n x n row-major. Returns false when it is singular.
bool solveLinearSystem(std::vector<double>& m, std::vector<double>& b, std::size_t n);

} // namespace vl::face
