#pragma once
// The map from the normalised face domain onto a user's mesh (in its texture space), fixed by the
// landmarks. A domain point (u,v) goes through three steps:
//  1. the mouth squeeze (face::squeezedMouthV): the rim of the domain's mouth hole closes to the
//     mouth line, leaving the user's own lip gap (measured from the lip landmarks) open;
//  2. the retraction: where the mesh does not reach the domain's border (a face mask rather than a
//     head), the outer part of the domain is compressed radially into the part the mesh covers, so
//     every domain point lands on the mesh while the face's middle (all landmarks) is untouched;
//  3. a thin-plate spline through the landmarks (canonical position -> the landmark's (u,v)).
// Coverage is measured on a grid over the canonical plane: the chosen islands' triangles cover it,
// and enclosed gaps in the coverage (eye and mouth openings, nostrils, cracks along UV seams) count
// as holes to be filled.
#include "core/face/Landmarks.h"
#include "core/face/ThinPlateSpline.h"
#include "core/face/UvMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vl::face {

struct CoverageHole {
    std::size_t cells = 0;
    Vec2 centre{0, 0}; // canonical position of its centroid
    std::string role;  // "eye_right", "eye_left", "mouth", or "other"
};

class FaceAlignment {
  public:
    // Throws InputError when a required landmark is missing or the landmarks do not determine a map
    // (coincident or collinear, e.g. left and right sharing (u,v) in a mirrored layout).
    FaceAlignment(const UvMesh& mesh, const UvLocator& locator, const FaceLandmarks& landmarks);

    // Steps 1 and 2 only: the canonical point a domain point is sampled at.
    Vec2 canonical(const Vec2& domain) const;
    // Step 3 only.
    Vec2 splineUV(const Vec2& canonicalPoint) const { return spline_(canonicalPoint); }

    // Coverage of a canonical point: -1 outside the mesh, 0 on it, k >= 1 inside hole k - 1.
    int coverageAt(const Vec2& canonicalPoint) const;
    const std::vector<CoverageHole>& holes() const { return holes_; }
    // Fraction of the domain [0,1]^2 whose canonical point (after step 1) the mesh covers directly or
    // through a hole, before the retraction; 1 for a mesh that reaches past the domain everywhere.
    double domainCoverage() const { return domainCoverage_; }
    // Fraction of the domain that the retraction moves.
    double retractedFraction() const { return retracted_; }
    // The lips' gap kept open at the rim (closedGap of face::squeezedMouthV).
    double closedGap() const { return closedGap_; }
    // Domain samples (on a 65 x 65 grid) where the map folds over (its Jacobian changes sign).
    std::size_t foldedSamples() const { return folded_; }

  private:
    void measureCoverage(const UvLocator& locator);
    void findBoundary();
    Vec2 retract(const Vec2& p) const;

    ThinPlateSpline spline_;
    double closedGap_ = 0.07;
    Vec2 lo_{-0.35, -0.35};
    double step_ = 1.0 / 320.0;
    int n_ = 0;
    std::vector<int> coverage_; // per canonical cell
    std::vector<CoverageHole> holes_;
    Vec2 centre_{0.5, 0.45};
    std::vector<double> boundary_; // coverage radius from centre_ per angle
    double domainCoverage_ = 0.0;
    double retracted_ = 0.0;
    std::size_t folded_ = 0;
};

} // namespace vl::face
