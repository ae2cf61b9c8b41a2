#include "core/face/HeadParts.h"

#include "core/common/Error.h"
#include "core/deform/CascadeSampler.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/FaceFrame.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace vl::face {

namespace {

// Where the lower teeth, the tongue and the cavity's floor follow the jaw: the chin, inside the
// mandible's plateau of jaw_open (core/face/FaceFields.cpp), so they move with it rigidly.
constexpr Vec2 kMandibleAnchor{kMouthU, 0.16};

// A part under construction: vertices with (u,v), anchors and weights added together.
struct PartBuilder {
    HeadPart part;
    int followAll = -1, followJaw = -1; // indices into part.follows
    Vec2 anchor = kMandibleAnchor;

    std::uint32_t add(const Vec3& p, const Vec2& uv) {
        part.rest.positions.push_back(p);
        part.rest.uvs.push_back(uv);
        part.anchors.push_back(anchor);
        for (auto& f : part.follows) f.weight.push_back(0.0);
        for (auto& o : part.own) o.displacement.emplace_back(0, 0, 0);
        return static_cast<std::uint32_t>(part.rest.positions.size() - 1);
    }
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        part.rest.triangles.push_back({a, b, c});
        part.rest.triangles.push_back({a, c, d});
    }
    int follow(int parameter) {
        part.follows.push_back({parameter, std::vector<double>(part.rest.positions.size(), 0.0), {}});
        return static_cast<int>(part.follows.size()) - 1;
    }
    int own(int parameter) {
        part.own.push_back({parameter, std::vector<Vec3>(part.rest.positions.size(), Vec3(0, 0, 0))});
        return static_cast<int>(part.own.size()) - 1;
    }
};

// Rings of `columns` vertices (closed around) stitched into a tube, with a cap vertex at each end.
void stitchTube(PartBuilder& b, std::uint32_t first, int rings, int columns, std::int64_t startCap,
                std::int64_t endCap) {
    const auto at = [&](int r, int c) {
        return first + static_cast<std::uint32_t>(r * columns + (c % columns));
    };
    for (int r = 0; r + 1 < rings; ++r)
        for (int c = 0; c < columns; ++c) b.quad(at(r, c), at(r + 1, c), at(r + 1, c + 1), at(r, c + 1));
    if (startCap >= 0)
        for (int c = 0; c < columns; ++c)
            b.part.rest.triangles.push_back({static_cast<std::uint32_t>(startCap), at(0, c + 1), at(0, c)});
    if (endCap >= 0)
        for (int c = 0; c < columns; ++c)
            b.part.rest.triangles.push_back(
                {static_cast<std::uint32_t>(endCap), at(rings - 1, c), at(rings - 1, c + 1)});
}

// Makes every triangle of the part face away from `inside` (or towards it when `inward`).
void orient(HeadPart& part, const std::function<Vec3(const Vec3&)>& inside, bool inward) {
    auto& m = part.rest;
    for (auto& t : m.triangles) {
        const Vec3 n =
            OpenMesh::cross(m.positions[t[1]] - m.positions[t[0]], m.positions[t[2]] - m.positions[t[0]]);
        const Vec3 centroid = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0;
        const bool outward = OpenMesh::dot(n, centroid - inside(centroid)) > 0.0;
        if (outward == inward) std::swap(t[1], t[2]);
    }
}

// --- Templates in the bundled face's coordinates (centimetres, +y up, +z forward) ----------------

struct BundledMouth {
    Vec3 centre;   // middle of the mouth (corners and lip middles)
    double upperZ; // z of the upper lip's rim in the middle
    double edgeY;  // height of the upper incisors' edge
};

BundledMouth bundledMouth() {
    const auto p = baseLandmarkPositions(makeBundledFace());
    const auto at = [&](Landmark l) { return p[static_cast<std::size_t>(l)]; };
    BundledMouth m;
    m.centre = (at(Landmark::MouthCornerRight) + at(Landmark::MouthCornerLeft) + at(Landmark::UpperLipMid) +
                at(Landmark::LowerLipMid)) /
               4.0;
    m.upperZ = at(Landmark::UpperLipMid)[2];
    m.edgeY = m.centre[1] - 0.08;
    return m;
}

// One row of teeth along a horseshoe arch: incisors in front, canines, then premolars, each tooth a
// crown with rounded corners (a scalloped edge) and a band of gum at its root. `upper` crowns hang
// down from the gum, lower ones stand up.
PartBuilder teethRow(bool upper, const BundledMouth& mouth, int jaw) {
    PartBuilder b;
    b.part.name = upper ? "teeth_upper" : "teeth_lower";
    if (!upper) b.followJaw = b.follow(jaw);
    const double sign = upper ? 1.0 : -1.0; // crowns grow away from the edge: up to the gum for upper
    const double archScale = upper ? 1.0 : 0.9;
    const double frontZ = mouth.upperZ - 0.62 - (upper ? 0.0 : 0.3);
    const double edgeY = upper ? mouth.edgeY : mouth.edgeY + 0.15;
    // Teeth from the middle out: central incisor, lateral incisor, canine, two premolars.
    const double widths[] = {0.85, 0.68, 0.78, 0.7, 0.7};
    const double crown[] = {1.0, 0.9, 1.05, 0.8, 0.75};
    double halfLength = 0.0;
    for (const double w : widths) halfLength += w * (upper ? 1.0 : 0.82);
    constexpr int kPerTooth = 3;
    constexpr int kSection = 8;
    // Arch: x along the width, z back; parametrised by arc length from the middle.
    const auto arch = [&](double s, Vec3& point, Vec3& outward) {
        const double t = s / halfLength; // -1..1
        point = Vec3(2.2 * archScale * t, 0.0, frontZ - 2.6 * archScale * t * t);
        const Vec3 tangent(2.2 * archScale, 0.0, -5.2 * archScale * t);
        outward = Vec3(-tangent[2], 0.0, tangent[0]).normalized();
        if (outward[2] < 0.0) outward = -outward;
        if (std::abs(t) > 1e-9 && outward[0] * t < 0.0) outward[0] = -outward[0];
    };
    // Cross-section (labial offset, height above the edge) from the labial gum around to the lingual.
    const double section[kSection][2] = {{-0.04, 1.15}, {0.06, 0.95}, {0.05, 0.5},  {0.0, 0.04},
                                         {-0.12, 0.0},  {-0.3, 0.15}, {-0.5, 0.75}, {-0.62, 1.15}};
    const std::uint32_t first = static_cast<std::uint32_t>(b.part.rest.positions.size());
    int rings = 0;
    std::vector<double> stations; // arc lengths of the rings, and which tooth / where across it
    std::vector<std::pair<int, double>> toothAt;
    for (int side = -1; side <= 1; side += 2) {
        double start = 0.0;
        for (int k = 0; k < 5; ++k) {
            const double w = widths[k] * (upper ? 1.0 : 0.82);
            for (int j = 0; j < kPerTooth; ++j) {
                const double across = (j + 0.5) / kPerTooth;
                stations.push_back(side * (start + across * w));
                toothAt.emplace_back(k, across);
            }
            start += w;
        }
    }
    // Order the stations from one end of the arch to the other.
    std::vector<std::size_t> order(stations.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t c) { return stations[a] < stations[c]; });
    for (const auto k : order) {
        Vec3 base, outward;
        arch(stations[k], base, outward);
        const auto [tooth, across] = toothAt[k];
        const double gap =
            std::pow(1.0 - std::sin(M_PI * across), 2.0); // 1 at a tooth's sides, 0 in its middle
        const double thick = tooth >= 3 ? 1.5 : tooth == 2 ? 1.2 : 1.0;
        for (int c = 0; c < kSection; ++c) {
            double labial = section[c][0] * thick, height = section[c][1];
            if (height < 0.95) height = height * crown[tooth]; // crown heights per tooth
            if (height < 0.35) height += 0.12 * gap;           // rounded corners: a scalloped edge
            if (c <= 3) labial -= 0.05 * gap;                  // and a slight dip between teeth
            const Vec3 p = base + outward * labial + Vec3(0.0, edgeY + sign * height, 0.0);
            const double t = 1.0 - section[c][1] / 1.15; // tile v: 0 at the gum's root, 1 at the edge
            b.add(p,
                  Vec2(double(HeadTile::Teeth) + 0.02 + 0.96 * double(rings) / double(order.size() - 1), t));
        }
        ++rings;
    }
    // Caps at both ends of the arch.
    Vec3 endBase, outward;
    arch(stations[order.front()] - 0.1, endBase, outward);
    const auto startCap = b.add(endBase + outward * -0.2 + Vec3(0, edgeY + sign * 0.7, 0),
                                Vec2(double(HeadTile::Teeth) + 0.01, 0.2));
    arch(stations[order.back()] + 0.1, endBase, outward);
    const auto endCap = b.add(endBase + outward * -0.2 + Vec3(0, edgeY + sign * 0.7, 0),
                              Vec2(double(HeadTile::Teeth) + 0.99, 0.2));
    stitchTube(b, first, rings, kSection, startCap, endCap);
    if (b.followJaw >= 0)
        std::fill(b.part.follows[b.followJaw].weight.begin(), b.part.follows[b.followJaw].weight.end(), 1.0);
    orient(
        b.part,
        [&](const Vec3& p) {
            // Inside a tooth: the arch's centre line at the point's height.
            const double t = std::clamp(p[0] / (2.2 * archScale), -1.0, 1.0);
            return Vec3(2.2 * archScale * t, edgeY + sign * 0.6, frontZ - 2.6 * archScale * t * t - 0.25);
        },
        false);
    return b;
}

// The tongue: a rounded, flattened body on the mouth's floor with its tip behind the lower incisors.
PartBuilder tongue(const BundledMouth& mouth, int jaw, int up, int out) {
    PartBuilder b;
    b.part.name = "tongue";
    const int followJaw = jaw >= 0 ? b.follow(jaw) : -1;
    const int ownUp = up >= 0 ? b.own(up) : -1;
    const int ownOut = out >= 0 ? b.own(out) : -1;
    const double tipZ = mouth.upperZ - 0.62 - 0.3 - 0.45;
    const double baseY = mouth.edgeY + 0.15 - 0.75;
    constexpr double kLength = 4.2;
    constexpr int kRings = 9, kAround = 10;
    const std::uint32_t first = static_cast<std::uint32_t>(b.part.rest.positions.size());
    for (int r = 0; r < kRings; ++r) {
        const double s = (r + 0.5) / kRings; // 0 root .. 1 tip
        const double halfWidth = 1.65 * std::sqrt(std::max(0.0, 1.0 - std::pow(s, 3.0)));
        const double top = 0.95 * std::sqrt(std::max(0.0, 1.0 - std::pow(s, 4.0))) + 0.15;
        const double z = tipZ - kLength * (1.0 - s);
        for (int c = 0; c < kAround; ++c) {
            const double phi = 2.0 * M_PI * c / kAround;
            const double x = halfWidth * std::cos(phi);
            const double y = std::sin(phi) >= 0.0 ? top * std::pow(std::sin(phi), 0.6) : 0.25 * std::sin(phi);
            b.add(Vec3(x, baseY + y, z), Vec2(double(HeadTile::Tongue) + 0.05 + 0.9 * c / kAround, s));
        }
    }
    const auto rootCap =
        b.add(Vec3(0, baseY + 0.3, tipZ - kLength - 0.2), Vec2(double(HeadTile::Tongue) + 0.5, 0.0));
    const auto tipCap = b.add(Vec3(0, baseY + 0.12, tipZ + 0.15), Vec2(double(HeadTile::Tongue) + 0.5, 1.0));
    stitchTube(b, first, kRings, kAround, rootCap, tipCap);
    // The tip follows the jaw more than the root; tongue_up lifts the tip to the ridge behind the
    // upper teeth, tongue_out brings it forward between the teeth.
    for (std::size_t i = 0; i < b.part.rest.positions.size(); ++i) {
        const double s = std::clamp(1.0 - (tipZ - b.part.rest.positions[i][2]) / kLength, 0.0, 1.0);
        if (followJaw >= 0) b.part.follows[followJaw].weight[i] = 0.55 + 0.45 * s;
        if (ownUp >= 0) b.part.own[ownUp].displacement[i] = Vec3(0, 1.25 * s * s, 0.25 * s * s);
        if (ownOut >= 0) b.part.own[ownOut].displacement[i] = Vec3(0, 0.8 * s * s * s, 0.8 * s * s * s);
    }
    orient(
        b.part,
        [&](const Vec3& p) {
            return Vec3(0, baseY + 0.3, std::clamp(p[2], tipZ - kLength + 0.5, tipZ - 0.5));
        },
        false);
    return b;
}

// An eyeball around `centre`: a sphere with the cornea's bulge in front; tile v is the angle from
// the front (iris and pupil are painted by it).
PartBuilder eyeball(bool left, const Vec3& centre) {
    PartBuilder b;
    b.part.name = left ? "eye_left" : "eye_right";
    const double latitudes[] = {0.03, 0.06, 0.09, 0.12, 0.15, 0.19, 0.26, 0.36, 0.5, 0.66, 0.83};
    constexpr int kAround = 14;
    const std::uint32_t first = static_cast<std::uint32_t>(b.part.rest.positions.size());
    const auto point = [&](double t, double phi) {
        const double angle = M_PI * t;
        const double bulge = t < 0.17 ? 0.07 * (1.0 - (t / 0.17) * (t / 0.17)) : 0.0;
        const double r = kEyeballRadius + bulge;
        return centre + Vec3(r * std::sin(angle) * std::cos(phi), r * std::sin(angle) * std::sin(phi),
                             r * std::cos(angle));
    };
    for (const double t : latitudes)
        for (int c = 0; c < kAround; ++c) {
            const double phi = 2.0 * M_PI * c / kAround;
            b.add(point(t, phi), Vec2(double(HeadTile::Eye) + 0.02 + 0.96 * c / kAround, t));
        }
    const auto front = b.add(point(0.0, 0.0), Vec2(double(HeadTile::Eye) + 0.5, 0.0));
    const auto back = b.add(point(1.0, 0.0), Vec2(double(HeadTile::Eye) + 0.5, 1.0));
    stitchTube(b, first, static_cast<int>(std::size(latitudes)), kAround, front, back);
    orient(
        b.part, [&](const Vec3&) { return centre; }, false);
    return b;
}

// The mouth cavity on the face's own lip rim: rings from the rim back to the throat, the rim ring
// following the lips exactly, deeper rings blending into the jaw (floor) or the skull (roof).
PartBuilder cavity(const DeformationCascade& cascade, const FaceFrame& frame, double scale, int jaw) {
    PartBuilder b;
    b.part.name = "mouth_cavity";
    const int all = b.follow(-1);
    const int followJaw = jaw >= 0 ? b.follow(jaw) : -1;
    const auto positions = baseLandmarkPositions(cascade);
    const auto at = [&](Landmark l) { return positions[static_cast<std::size_t>(l)]; };
    const Vec3 centre = (at(Landmark::MouthCornerRight) + at(Landmark::MouthCornerLeft) +
                         at(Landmark::UpperLipMid) + at(Landmark::LowerLipMid)) /
                        4.0;
    const DeformationStage* base = nullptr;
    for (const auto& stage : cascade.stages)
        if (stage.kind == StageKind::Constant) base = &stage;
    // Rim points: the upper rim from the right corner to the left one, then the lower rim back.
    constexpr int kHalf = 8;
    std::vector<Vec2> rim;
    std::vector<double> angle;
    for (int j = 0; j <= kHalf; ++j) {
        const double u = kMouthU - kMouthHalfWidth + 2.0 * kMouthHalfWidth * j / kHalf;
        rim.emplace_back(u, kMouthV + mouthHoleHalfHeight(u));
        angle.push_back(M_PI * (1.0 - double(j) / kHalf));
    }
    for (int j = kHalf - 1; j >= 1; --j) {
        const double u = kMouthU - kMouthHalfWidth + 2.0 * kMouthHalfWidth * j / kHalf;
        rim.emplace_back(u, kMouthV - mouthHoleHalfHeight(u));
        angle.push_back(M_PI * (1.0 + double(j) / kHalf));
    }
    const int columns = static_cast<int>(rim.size());
    // Depth, half-width, roof and floor heights of the rings (bundled centimetres), blend from the rim.
    const double depth[] = {0.0, 0.7, 1.7, 2.9, 4.1, 5.1};
    const double width[] = {0.0, 1.5, 2.1, 2.35, 2.2, 1.5};
    const double roof[] = {0.0, 0.45, 0.85, 1.1, 1.15, 0.9};
    const double floorDepth[] = {0.0, 0.55, 1.05, 1.6, 1.7, 1.3};
    const double blend[] = {0.0, 0.55, 0.9, 1.0, 1.0, 1.0};
    const double follow[] = {1.0, 0.7, 0.35, 0.12, 0.0, 0.0};
    constexpr int kRings = 6;
    const std::uint32_t first = static_cast<std::uint32_t>(b.part.rest.positions.size());
    for (int r = 0; r < kRings; ++r)
        for (int c = 0; c < columns; ++c) {
            const Vec3 rimPoint = base->field.at(rim[c][0], rim[c][1]) - frame.forward * (0.12 * scale);
            const double x = width[r] * std::cos(angle[c]);
            const double s = std::sin(angle[c]);
            const double y = s >= 0.0 ? roof[r] * s : floorDepth[r] * s;
            const Vec3 inside = centre + (frame.forward * -depth[r] + frame.right * x + frame.up * y) * scale;
            b.anchor = rim[c];
            const auto v = b.add(
                rimPoint * (1.0 - blend[r]) + inside * blend[r],
                Vec2(double(HeadTile::Cavity) + 0.02 + 0.96 * angle[c] / (2.0 * M_PI), double(r) / kRings));
            b.part.follows[all].weight[v] = follow[r];
            if (followJaw >= 0 && s < 0.0) b.part.follows[followJaw].weight[v] = 1.0 - follow[r];
        }
    b.anchor = Vec2(kMouthU, kMouthV - kMouthHalfHeight);
    const auto back = b.add(centre - (frame.forward * 5.8 + frame.up * 0.2) * scale,
                            Vec2(double(HeadTile::Cavity) + 0.5, 1.0));
    if (followJaw >= 0) {
        b.part.follows[followJaw].weight[back] = 0.5;
        // The floor's share of the jaw is the mandible's (as the lower teeth's), not the lip rim's: near
        // the corners the rim follows the jaw less, and a floor following it would rise in front of the
        // lower teeth.
        b.part.follows[followJaw].anchors.assign(b.part.rest.positions.size(), kMandibleAnchor);
    }
    stitchTube(b, first, kRings, columns, -1, back);
    // Faces point into the cavity (its inside is what is seen through the open mouth).
    const Vec3 axisPoint = centre - frame.forward * (2.5 * scale);
    orient(
        b.part, [&](const Vec3&) { return axisPoint; }, true);
    return b;
}

// A direction of the bundled face in `face`'s frame.
Vec3 carried(const Vec3& d, const FaceFrame& bundled, const FaceFrame& face) {
    return face.rotate(Vec3(OpenMesh::dot(d, bundled.right), OpenMesh::dot(d, bundled.up),
                            OpenMesh::dot(d, bundled.forward)));
}

// Carries a bundled-template part to a face: p -> target + R * scale * (p - source), R taking the
// bundled frame's axes to the face's; own displacements rotate and scale the same way.
void place(HeadPart& part, const Vec3& source, const Vec3& target, const FaceFrame& bundled,
           const FaceFrame& face, double scale) {
    const auto rotate = [&](const Vec3& d) { return carried(d, bundled, face); };
    for (auto& p : part.rest.positions) p = target + rotate(p - source) * scale;
    for (auto& o : part.own)
        for (auto& d : o.displacement) d = rotate(d) * scale;
    // A mirrored frame (a mirrored mesh) flips the winding: keep faces pointing out.
    const Vec3 x = rotate(Vec3(1, 0, 0)), y = rotate(Vec3(0, 1, 0)), z = rotate(Vec3(0, 0, 1));
    if (OpenMesh::dot(OpenMesh::cross(x, y), z) < 0.0)
        for (auto& t : part.rest.triangles) std::swap(t[1], t[2]);
}

// The middle between an eye's corners.
Vec3 eyeMiddle(const std::array<Vec3, kLandmarkCount>& p, bool left) {
    const Landmark inner = left ? Landmark::EyeInnerLeft : Landmark::EyeInnerRight;
    const Landmark outer = left ? Landmark::EyeOuterLeft : Landmark::EyeOuterRight;
    return (p[static_cast<std::size_t>(inner)] + p[static_cast<std::size_t>(outer)]) * 0.5;
}

const std::array<Vec3, kLandmarkCount>& bundledLandmarkPositions() {
    static const auto positions = baseLandmarkPositions(makeBundledFace());
    return positions;
}

} // namespace

Vec3 carriedEyeballCentre(const std::array<Vec3, kLandmarkCount>& landmarks, bool left) {
    const FaceFrame& bundled = bundledFaceFrame();
    const FaceFrame face = frameFromLandmarks(landmarks);
    const Vec3 source = eyeMiddle(bundledLandmarkPositions(), left);
    return eyeMiddle(landmarks, left) +
           carried(eyeballCentre(Individual::Bundled, left ? 1.0 : -1.0) - source, bundled, face) *
               face.scaleTo(bundled);
}

std::vector<HeadPart> makeHeadParts(const DeformationCascade& cascade) {
    const FaceFrame& bundled = bundledFaceFrame();
    const FaceFrame face = faceFrameOf(cascade);
    const double scale = face.scaleTo(bundled);
    static const BundledMouth mouth = bundledMouth();
    const auto& bundledLandmarks = bundledLandmarkPositions();
    const auto landmarks = baseLandmarkPositions(cascade);
    const auto at = [](const std::array<Vec3, kLandmarkCount>& p, Landmark l) {
        return p[static_cast<std::size_t>(l)];
    };
    const auto mouthCentre = [&](const std::array<Vec3, kLandmarkCount>& p) {
        return (at(p, Landmark::MouthCornerRight) + at(p, Landmark::MouthCornerLeft) +
                at(p, Landmark::UpperLipMid) + at(p, Landmark::LowerLipMid)) /
               4.0;
    };
    const int jaw = cascade.findParameter("jaw_open");
    std::vector<HeadPart> parts;
    for (const bool left : {false, true}) { // carriedEyeballCentre() is where this puts the centre
        HeadPart eye = eyeball(left, eyeballCentre(Individual::Bundled, left ? 1.0 : -1.0)).part;
        place(eye, eyeMiddle(bundledLandmarks, left), eyeMiddle(landmarks, left), bundled, face, scale);
        parts.push_back(std::move(eye));
    }
    for (const bool upper : {true, false}) {
        HeadPart row = teethRow(upper, mouth, jaw).part;
        place(row, mouth.centre, mouthCentre(landmarks), bundled, face, scale);
        parts.push_back(std::move(row));
    }
    HeadPart t =
        tongue(mouth, jaw, cascade.findParameter("tongue_up"), cascade.findParameter("tongue_out")).part;
    place(t, mouth.centre, mouthCentre(landmarks), bundled, face, scale);
    parts.push_back(std::move(t));
    parts.push_back(cavity(cascade, face, scale, jaw).part);
    // Parameters the cascade does not have are not followed.
    for (auto& part : parts) {
        std::erase_if(part.follows, [&](const HeadPart::Follow& f) {
            return f.parameter >= static_cast<int>(cascade.parameters.size());
        });
        std::erase_if(part.own, [](const HeadPart::Own& o) { return o.parameter < 0; });
    }
    return parts;
}

HeadPartsSampler::HeadPartsSampler(const DeformationCascade& cascade, std::span<const HeadPart> parts) {
    validateCascade(cascade);
    ranges_.name = cascade.name;
    ranges_.parameters = cascade.parameters;
    const std::size_t k = cascade.parameters.size();
    std::size_t first = 0;
    for (std::size_t s = 0; s < cascade.stages.size(); ++s)
        if (cascade.stages[s].kind == StageKind::Constant) first = s;
    // Per-parameter field displacement at an anchor (cached: many vertices share one).
    std::map<std::pair<double, double>, std::vector<Vec3>> cache;
    const auto fieldsAt = [&](const Vec2& a) -> const std::vector<Vec3>& {
        auto it = cache.find({a[0], a[1]});
        if (it != cache.end()) return it->second;
        std::vector<Vec3> d(k, Vec3(0, 0, 0));
        for (std::size_t s = first + 1; s < cascade.stages.size(); ++s)
            d[cascade.stages[s].parameter] += cascade.stages[s].field.at(a[0], a[1]);
        return cache.emplace(std::pair{a[0], a[1]}, std::move(d)).first->second;
    };
    displacement_.assign(k, {});
    std::size_t offset = 0;
    for (const auto& part : parts) {
        const std::size_t n = part.rest.positions.size();
        rest_.insert(rest_.end(), part.rest.positions.begin(), part.rest.positions.end());
        const auto column = [&](std::size_t parameter) -> std::vector<Vec3>& {
            auto& d = displacement_[parameter];
            if (d.empty()) d.assign(offset + n, Vec3(0, 0, 0));
            d.resize(offset + n, Vec3(0, 0, 0));
            return d;
        };
        for (const auto& f : part.follows)
            for (std::size_t i = 0; i < n; ++i) {
                if (f.weight[i] == 0.0) continue;
                const auto& d = fieldsAt(f.anchors.empty() ? part.anchors[i] : f.anchors[i]);
                for (std::size_t p = 0; p < k; ++p) {
                    if (f.parameter >= 0 && static_cast<std::size_t>(f.parameter) != p) continue;
                    if (d[p][0] == 0.0 && d[p][1] == 0.0 && d[p][2] == 0.0) continue;
                    column(p)[offset + i] += d[p] * f.weight[i];
                }
            }
        for (const auto& o : part.own)
            for (std::size_t i = 0; i < n; ++i)
                column(static_cast<std::size_t>(o.parameter))[offset + i] += o.displacement[i];
        offset += n;
    }
    for (auto& d : displacement_)
        if (!d.empty()) d.resize(rest_.size(), Vec3(0, 0, 0));
}

std::vector<Vec3> HeadPartsSampler::evaluate(std::span<const double> q) const {
    checkParameterValues(ranges_, q);
    std::vector<Vec3> out = rest_;
    for (std::size_t p = 0; p < displacement_.size(); ++p) {
        if (q[p] == 0.0 || displacement_[p].empty()) continue;
        for (std::size_t i = 0; i < out.size(); ++i) out[i] += displacement_[p][i] * q[p];
    }
    return out;
}

std::vector<Vec3> HeadPartsSampler::displacement(std::size_t parameter) const {
    if (parameter >= displacement_.size())
        throwInputError("head parts", "no parameter " + std::to_string(parameter) + " (the face has " +
                                          std::to_string(displacement_.size()) + ")");
    const auto& d = displacement_[parameter];
    return d.empty() ? std::vector<Vec3>(rest_.size(), Vec3(0, 0, 0)) : d;
}

MeshData partsMesh(std::span<const HeadPart> parts) {
    MeshData mesh;
    for (const auto& part : parts) {
        const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), part.rest.positions.begin(), part.rest.positions.end());
        mesh.uvs.insert(mesh.uvs.end(), part.rest.uvs.begin(), part.rest.uvs.end());
        for (const auto& t : part.rest.triangles)
            mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
    return mesh;
}

VisemeSet generateHeadVisemeSet(const DeformationCascade& cascade, const MeshData& uvMesh,
                                std::span<const VisemeParameters> visemes, std::span<const HeadPart> parts) {
    VisemeSet set = generateVisemeSet(cascade, uvMesh, visemes);
    if (parts.empty()) return set;
    const HeadPartsSampler sampler(cascade, parts);
    const MeshData extra = partsMesh(parts);
    const auto offset = static_cast<std::uint32_t>(set.neutral.positions.size());
    const auto append = [&](std::vector<Vec3>& positions, std::span<const double> q) {
        const auto p = sampler.evaluate(q);
        positions.insert(positions.end(), p.begin(), p.end());
    };
    append(set.neutral.positions, cascade.defaults());
    set.neutral.uvs.insert(set.neutral.uvs.end(), extra.uvs.begin(), extra.uvs.end());
    for (const auto& t : extra.triangles)
        set.neutral.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    for (std::size_t k = 0; k < set.visemes.size(); ++k)
        append(set.visemes[k].positions, parameterVector(cascade, visemes[k]));
    return set;
}

} // namespace vl::face
