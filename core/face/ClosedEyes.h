#pragma once
// Closed eyes found from the shape of a face: with no eye opening to follow, each eye lies in its eye
// socket, the depression between the brow and the cheek beside the nose: its height is that of the most
// recessed part of the face's front surface (its depth below the average around it, at the socket's
// scale) on each side of the symmetry plane above the nose tip, and its middle is the centre of symmetry
// of the lids' relief along that line (a bulge where the lids lie over the eyeball, a dip between two
// ridges where they fold into the socket: both are symmetric about the eye's middle). The two eyes,
// averaged as mirror images, give the eye centres; the corners lie either side of each centre at
// average proportions (scaled by the distance between the centres found).
//
// Everything is in the face's frame (core/face/GeometryLandmarks.cpp): the origin at the nose tip,
// x towards the face's left, y up, z forward (out of the face), so the result does not depend on the
// mesh's pose, units or density.
#include "core/mesh/Mesh.h"

#include <array>
#include <span>
#include <string>

namespace vl::face {

struct ClosedEyes {
    bool found = false;
    // Corners in the face's frame: [0] the right eye (x < 0), [1] the left eye.
    std::array<Vec3, 2> inner{Vec3(0, 0, 0), Vec3(0, 0, 0)}, outer{Vec3(0, 0, 0), Vec3(0, 0, 0)};
    std::array<Vec3, 2> centre{Vec3(0, 0, 0), Vec3(0, 0, 0)}; // each eye's centre as found (unmirrored)
    double confidence = 0.0;
    std::string method;
};

// The eye corners relative to the eye's centre, per unit of the distance between the eye centres:
// inner and outer corner of the left eye (x > 0); the right eye mirrors. The default is the adult
// average (Farkas, "Anthropometry of the Head and Face", 1994: inner corners about 3.3 cm apart, outer
// about 9 cm, so an eye is 0.46 of the distance between the centres wide).
struct EyeProportions {
    Vec3 inner{-0.23, 0, 0}, outer{0.23, 0, 0};
};

// `triangles`: the face's surface in its frame (see above). `mouthDepth`: how far below the nose tip
// the mouth is (the vertical unit of the search: the sockets lie above the nose tip, within about
// that distance); `mouthWidth`: between the mouth corners (the horizontal unit).
ClosedEyes findClosedEyes(std::span<const std::array<Vec3, 3>> triangles, double mouthDepth,
                          double mouthWidth, const EyeProportions& proportions = {});

} // namespace vl::face
