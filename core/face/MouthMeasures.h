#pragma once
// What a viseme mesh's mouth looks like, measured on the mesh: how far the lips are apart at the
// midline, how wide the mouth is, how far the lips stand forward, and how much of the teeth and the
// tongue can be seen from the front through the opening. The mesh is a head in the bundled (u,v)
// layout, as `visemelab visemes` writes it: the skin with (u,v) on the face domain (the mouth corners
// and lip middles are vertices of it, core/face/FaceDomain.h), then the head's parts with (u,v) in
// their tiles (face::HeadTile; the two rows of teeth are separate pieces of the teeth tile). The face
// looks along +z with +y up (the bundled faces' frame); lengths are in the mesh's units.
#include "core/mesh/Mesh.h"

#include <array>
#include <optional>
#include <string_view>

namespace vl::face {

struct MouthMeasures {
    // The inner lip contour's landmarks: mouth corners (the face's right one, then its left one) and
    // the middles of the upper and lower lip.
    Vec3 cornerRight{0, 0, 0}, cornerLeft{0, 0, 0}, upperLip{0, 0, 0}, lowerLip{0, 0, 0};
    double opening = 0.0; // upper lip middle above the lower lip middle (y); about 0 when closed
    // The opening's outline seen from the front: the upper lip's inner contour above the lower one's
    // (y) at the fractions kOpeningProfileAt of the way from the middle to each mouth corner (in x;
    // the middle is halfway between the corners), the two sides averaged. A rounded opening falls
    // off like an ellipse (about 1, 0.97, 0.87, 0.66 of the middle's); a trapezoid stays near the
    // middle's height to three quarters of the way and drops at the corners.
    std::array<double, 4> openingProfile{};
    double lipDistance = 0.0; // the two lip middles apart (3D)
    double width = 0.0;       // mouth corner to mouth corner (3D)
    // The foremost (z) point of each lip's outer surface near the midline.
    double upperLipFront = 0.0, lowerLipFront = 0.0;
    // Areas seen from the front (orthographic along -z, in squared units) of each part.
    double upperTeethSeen = 0.0, lowerTeethSeen = 0.0, tongueSeen = 0.0;
    // Measured on the central incisors (the middle third of each row's width); empty when the mesh has
    // no teeth. The lower lip near the midline to the nearest upper incisor vertex (labiodental
    // contact); the upper incisors' edge above the lower ones' (how far the teeth are apart, negative
    // when they overlap); the tongue's foremost point ahead of the upper incisors' front (positive: the
    // tip is out between the teeth).
    std::optional<double> lowerLipToUpperTeeth, teethGap, tongueAhead;
};

// Throws InputError (naming `where`) when the mesh has no (u,v), when a landmark of the mouth is not
// a vertex of its skin, or when its teeth are not two separate rows.
MouthMeasures measureMouth(const MeshData& head, std::string_view where = "mesh");

// Where openingProfile measures: fractions of the way from the mouth's middle to its corners.
constexpr std::array<double, 4> kOpeningProfileAt{0.0, 0.25, 0.5, 0.75};

// The front view that measures the areas seen has pixels of this fraction of the mouth's width.
constexpr double kMouthPixelPerWidth = 1.0 / 400.0;

} // namespace vl::face
