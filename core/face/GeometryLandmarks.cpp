// Landmarks from the shape of an unknown face mesh (any pose, units or UV layout):
//  1. the outside of the mesh (visible from around it) and its bilateral symmetry plane;
//  2. the nose tip: the point near the plane that stands out most from its surroundings;
//  3. forward: the face's average normal around the nose; up: the side of the nose where the bridge
//     runs (its profile falls slowly), confirmed by where the eyes and the mouth are;
//  4. the mouth and eye openings: boundary loops of the face's surface in the right places (mouth
//     corners, the lips' middles and quarter points, eye corners);
//  5. a closed mouth from the profile: the groove between the lips below the nose, followed sideways
//     to its ends;
//  6. closed eyes (no openings) from the eye sockets: core/face/ClosedEyes.h;
//  7. whatever is still missing, estimated from the bundled face's proportions.
#include "core/face/GeometryLandmarks.h"

#include "core/face/BundledFace.h"
#include "core/face/ClosedEyes.h"
#include "core/face/FaceFrame.h"
#include "core/face/MeshGeometry.h"
#include "core/face/SurfaceAnalysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace vl::face {

namespace {

struct Frame {
    Vec3 origin, right, up, forward;
    Vec3 local(const Vec3& p) const {
        const Vec3 d = p - origin;
        return Vec3(OpenMesh::dot(d, right), OpenMesh::dot(d, up), OpenMesh::dot(d, forward));
    }
    Vec3 world(const Vec3& l) const { return origin + right * l[0] + up * l[1] + forward * l[2]; }
};

struct Loop {
    std::vector<Vec3> local; // points in the frame
    Vec3 centre{0, 0, 0};
    Vec3 lo{0, 0, 0}, hi{0, 0, 0};
    double perimeter = 0.0;
    double width() const { return hi[0] - lo[0]; }
    double height() const { return hi[1] - lo[1]; }
};

Loop describeLoop(const std::vector<std::uint32_t>& loop, const WeldedSurface& s, const Frame& f) {
    Loop l;
    for (const auto v : loop) l.local.push_back(f.local(s.points[v]));
    l.lo = l.hi = l.local.front();
    for (std::size_t k = 0; k < l.local.size(); ++k) {
        l.centre += l.local[k] / double(l.local.size());
        l.lo.minimize(l.local[k]);
        l.hi.maximize(l.local[k]);
        l.perimeter += (l.local[(k + 1) % l.local.size()] - l.local[k]).norm();
    }
    return l;
}

// Points where the closed polyline crosses the vertical line x = at (interpolated), in the frame.
std::vector<Vec3> crossings(const Loop& loop, double at) {
    std::vector<Vec3> out;
    const auto& p = loop.local;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const Vec3 &a = p[k], &b = p[(k + 1) % p.size()];
        if ((a[0] - at) * (b[0] - at) > 0.0 || a[0] == b[0]) continue;
        const double t = (at - a[0]) / (b[0] - a[0]);
        if (t < 0.0 || t > 1.0) continue;
        out.push_back(a + (b - a) * t);
    }
    return out;
}

struct MouthFit {
    double score = 0.0;
    std::size_t loop = 0;
};
struct EyeFit {
    double score = 0.0;
    std::size_t right = 0, left = 0;
};

// How well a loop fits the mouth opening of a face whose nose tip is the frame's origin and whose
// size is about `size` (the nose's protrusion scale).
double mouthScore(const Loop& l, double size) {
    const double w = l.width(), h = l.height();
    if (w < 0.4 * size || w > 4.0 * size) return 0.0;
    if (h > 1.2 * w) return 0.0;
    if (l.centre[1] > -0.2 * size || l.centre[1] < -3.5 * size) return 0.0; // below the nose
    const double centred = std::max(0.0, 1.0 - std::abs(l.centre[0]) / (0.25 * w));
    const double across = std::min(l.lo[0] < 0.0 ? 1.0 : 0.0, l.hi[0] > 0.0 ? 1.0 : 0.0);
    return centred * across * (1.0 + w / size);
}

double eyeScore(const Loop& r, const Loop& l, double size) {
    if (r.centre[0] >= 0.0 || l.centre[0] <= 0.0) return 0.0;
    for (const Loop* e : {&r, &l}) {
        if (e->width() < 0.3 * size || e->width() > 2.5 * size) return 0.0;
        if (e->centre[1] < -0.5 * size || e->centre[1] > 3.0 * size)
            return 0.0; // about level with the nose or above
        if (e->height() > 1.5 * e->width()) return 0.0;
    }
    const double symmetric =
        std::max(0.0, 1.0 - (std::abs(r.centre[0] + l.centre[0]) + std::abs(r.centre[1] - l.centre[1])) /
                                (0.5 * (r.width() + l.width())));
    const double similar = std::min(r.width(), l.width()) / std::max(r.width(), l.width());
    return symmetric * similar;
}

// Where the face's surface is searched for a landmark's (u,v): its own island first (a point on an
// opening's rim also lies on whatever is attached there), then the whole face surface.
struct Surfaces {
    std::vector<bool> island, region;
    double tolerance = 0.0;
};

FoundLandmark fromPoint(const UvMesh& mesh, const Surfaces& where, const Vec3& p, double confidence,
                        std::string method, LandmarkSource source = LandmarkSource::Geometry) {
    UvHit hit = closestSurfacePoint(mesh, p, where.island);
    if (!hit.found || (hit.position - p).norm() > where.tolerance)
        hit = closestSurfacePoint(mesh, p, where.region);
    FoundLandmark found;
    if (!hit.found) return found;
    found.source = source;
    found.confidence = confidence;
    found.method = std::move(method);
    found.position = hit.position;
    found.uv = uvOf(mesh, hit);
    found.island = static_cast<int>(mesh.island[hit.triangle]);
    return found;
}

// Sections of the face's surface by planes x = const of the frame: the front-most depth (z) of the
// section curve in bins along y. Built on triangles, so coarse meshes give continuous curves.
class Section {
  public:
    Section(const WeldedSurface& s, const std::vector<Triangle>& triangles, const Frame& f) {
        for (const auto& t : triangles) {
            std::array<Vec3, 3> p{f.local(s.points[t[0]]), f.local(s.points[t[1]]), f.local(s.points[t[2]])};
            local_.push_back(p);
        }
    }
    // The groove (a local minimum of the front depth between two higher points) nearest `near` on the
    // section x = at between heights yHigh > yLow, if one is at least 0.02 * size deep.
    std::optional<Vec3> groove(double at, double yHigh, double yLow, double size,
                               std::optional<double> near = {}) const {
        constexpr int kBins = 48;
        const double step = (yHigh - yLow) / kBins;
        std::vector<double> front(kBins, std::numeric_limits<double>::quiet_NaN());
        for (const auto& p : local_) {
            // The segment where the plane x = at cuts the triangle.
            std::vector<Vec3> cut;
            for (int k = 0; k < 3; ++k) {
                const Vec3 &a = p[k], &b = p[(k + 1) % 3];
                if ((a[0] - at) * (b[0] - at) > 0.0 || a[0] == b[0]) continue;
                cut.push_back(a + (b - a) * ((at - a[0]) / (b[0] - a[0])));
            }
            if (cut.size() < 2) continue;
            for (int k = 0; k <= 8; ++k) {
                const Vec3 q = cut[0] + (cut[1] - cut[0]) * (k / 8.0);
                const int b = static_cast<int>((q[1] - yLow) / step);
                if (b < 0 || b >= kBins) continue;
                if (std::isnan(front[b]) || q[2] > front[b]) front[b] = q[2];
            }
        }
        // Fill gaps by linear interpolation, then look for the deepest-enough local minimum.
        for (int b = 0; b < kBins; ++b) {
            if (!std::isnan(front[b])) continue;
            int l = b - 1, r = b + 1;
            while (l >= 0 && std::isnan(front[l])) --l;
            while (r < kBins && std::isnan(front[r])) ++r;
            if (l < 0 || r >= kBins) continue;
            front[b] = front[l] + (front[r] - front[l]) * (b - l) / double(r - l);
        }
        if (std::getenv("VL_DEBUG") && !near) {
            for (int b = kBins - 1; b >= 0; --b)
                std::fprintf(stderr, "%.2f:%.2f ", yLow + (b + 0.5) * step, front[b]);
            std::fprintf(stderr, "\n");
        }
        std::optional<Vec3> best;
        double bestKey = std::numeric_limits<double>::max();
        const int side = std::max(2, static_cast<int>(0.5 * size / step));
        for (int b = 1; b + 1 < kBins; ++b) {
            if (std::isnan(front[b]) || std::isnan(front[b - 1]) || std::isnan(front[b + 1])) continue;
            if (front[b] > front[b - 1] || front[b] > front[b + 1]) continue;
            // Depth below the highest point on each side, within half the nose's size.
            double above = -1e300, below = -1e300;
            for (int k = 1; k <= side; ++k) {
                if (b + k < kBins && !std::isnan(front[b + k])) above = std::max(above, front[b + k]);
                if (b - k >= 0 && !std::isnan(front[b - k])) below = std::max(below, front[b - k]);
            }
            const double depth = std::min(above, below) - front[b];
            if (depth < 0.02 * size) continue;
            const double y = yLow + (b + 0.5) * step;
            // Sideways: the groove nearest the last height. On the profile: the deepest groove whose two
            // sides are about as high (the lips); under the nose one side is the much higher nose.
            const double key = near ? std::abs(y - *near) : -depth / (1.0 + std::abs(above - below) / depth);
            if (key < bestKey) {
                bestKey = key;
                best = Vec3(at, y, front[b]);
            }
        }
        return best;
    }

  private:
    std::vector<std::array<Vec3, 3>> local_;
};

// Eyes estimated from proportions move to the eye sockets: on each side, the most recessed point of
// the surface near the estimate (the surface below the mean of its surroundings); both sides move
// by the mirrored average, keeping the pair symmetric.
void refineEstimatedEyes(const WeldedSurface& s, const std::vector<std::uint32_t>& outside,
                         const Vec3& centroid, const Frame& frame, const UvMesh& mesh, const Surfaces& where,
                         FaceLandmarks& lm) {
    const Landmark corners[2][2] = {{Landmark::EyeOuterRight, Landmark::EyeInnerRight},
                                    {Landmark::EyeOuterLeft, Landmark::EyeInnerLeft}};
    for (const auto& side : corners)
        for (const auto l : side)
            if (lm[l].source != LandmarkSource::Estimate) return;
    Vec3 centre[2];
    for (int k = 0; k < 2; ++k)
        centre[k] = frame.local((lm[corners[k][0]].position + lm[corners[k][1]].position) * 0.5);
    const double eyeDistance = (centre[1] - centre[0]).norm();
    if (eyeDistance <= 0.0) return;
    const PointIndex index(s.points, outside, eyeDistance / 20.0);
    std::vector<std::uint32_t> near, around;
    Vec3 found[2];
    for (int k = 0; k < 2; ++k) {
        double best = 0.0;
        std::vector<std::pair<double, Vec3>> recessed;
        index.within(frame.world(centre[k]), 0.3 * eyeDistance, near);
        for (const auto v : near) {
            index.within(s.points[v], 0.25 * eyeDistance, around);
            if (around.size() < 6) continue;
            Vec3 mean(0, 0, 0);
            double weight = 0.0;
            for (const auto q : around) {
                mean += s.points[q] * s.areas[q];
                weight += s.areas[q];
            }
            Vec3 n = s.normals[v];
            if (OpenMesh::dot(n, s.points[v] - centroid) < 0) n = -n;
            const double recess = OpenMesh::dot(mean / weight - s.points[v], n);
            best = std::max(best, recess);
            recessed.emplace_back(recess, frame.local(s.points[v]));
        }
        if (best < 0.02 * eyeDistance) return; // no socket to speak of
        // The middle of the deepest part (recess above half the deepest), weighted by recess.
        Vec3 sum(0, 0, 0);
        double weight = 0.0;
        for (const auto& [recess, local] : recessed)
            if (recess > 0.5 * best) {
                sum += local * recess;
                weight += recess;
            }
        found[k] = sum / weight;
    }
    // The mirrored average offset (x symmetric, y and z shared).
    const Vec3 shift((found[1][0] - centre[1][0] - (found[0][0] - centre[0][0])) * 0.5,
                     0.5 * (found[0][1] - centre[0][1] + found[1][1] - centre[1][1]), 0.0);
    for (int k = 0; k < 2; ++k)
        for (const auto l : corners[k]) {
            Vec3 local = frame.local(lm[l].position);
            local[0] += k == 0 ? -shift[0] : shift[0];
            local[1] += shift[1];
            lm[l] = fromPoint(
                mesh, where, frame.world(local), 0.35,
                "eye socket (the most recessed point near the estimate) with the face's proportions",
                LandmarkSource::Estimate);
        }
}

} // namespace

GeometryFinding findLandmarksFromGeometry(const UvMesh& mesh) {
    GeometryFinding out;
    const WeldedSurface s = weldSurface(mesh);
    if (s.triangles.empty() || s.diagonal <= 0.0) return out;
    const double diag = s.diagonal;

    // 1. The outside: islands mostly seen from around the mesh.
    const auto visible = visibleTriangles(s);
    std::vector<double> islandArea(mesh.islandCount, 0.0), islandSeen(mesh.islandCount, 0.0);
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        const auto& w = s.triangles[t];
        const double a =
            0.5 * OpenMesh::cross(s.points[w[1]] - s.points[w[0]], s.points[w[2]] - s.points[w[0]]).norm();
        islandArea[mesh.island[t]] += a;
        if (visible[t]) islandSeen[mesh.island[t]] += a;
    }
    std::vector<bool> outsideIsland(mesh.islandCount);
    for (std::size_t k = 0; k < mesh.islandCount; ++k)
        outsideIsland[k] = islandArea[k] > 0.0 && islandSeen[k] >= 0.25 * islandArea[k];
    std::vector<bool> outsidePoint(s.points.size(), false);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
        if (visible[t] && outsideIsland[mesh.island[t]])
            for (const auto v : s.triangles[t]) outsidePoint[v] = true;
    std::vector<std::uint32_t> outside;
    for (std::uint32_t v = 0; v < s.points.size(); ++v)
        if (outsidePoint[v]) outside.push_back(v);
    if (outside.size() < 20) {
        out.notes.push_back("geometry: too little of the mesh is visible from outside to find a face");
        return out;
    }
    Vec3 centroid(0, 0, 0);
    for (const auto v : outside) centroid += s.points[v] / double(outside.size());

    const SymmetryPlane plane = findSymmetryPlane(s, outside);
    const double symmetryConfidence = std::clamp(1.0 - plane.error / 0.02, 0.0, 1.0);
    out.notes.push_back("geometry: symmetry plane found, mirror mismatch " +
                        std::to_string(plane.error * 100.0).substr(0, 4) + "% of the mesh size");

    // Boundary points of the outside surface (protrusion is not measured across a cut).
    std::vector<Triangle> outsideTriangles;
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
        if (outsideIsland[mesh.island[t]]) outsideTriangles.push_back(s.triangles[t]);
    std::set<std::uint32_t> boundary;
    for (const auto& loop : boundaryLoops(outsideTriangles)) boundary.insert(loop.begin(), loop.end());
    std::vector<std::uint32_t> boundaryList(boundary.begin(), boundary.end());

    // 2. The nose tip: the greatest protrusion above the surroundings near the plane, over scales.
    const PointIndex index(s.points, outside, diag / 80.0);
    const PointIndex boundaryIndex(s.points, boundaryList, diag / 80.0);
    const double scales[] = {0.04, 0.06, 0.09, 0.13};
    std::vector<std::uint32_t> near;
    double bestScore = 0.0, bestScale = 0.0;
    std::int64_t nose = -1;
    for (const auto v : outside) {
        if (std::abs(plane.signedDistance(s.points[v])) > 0.015 * diag) continue;
        Vec3 n = s.normals[v];
        if (OpenMesh::dot(n, s.points[v] - centroid) < 0) n = -n; // outward, whatever the winding
        for (const double k : scales) {
            const double r = k * diag;
            if (!boundaryList.empty() && boundaryIndex.nearest(s.points[v], 0.8 * r) >= 0) continue;
            index.within(s.points[v], r, near);
            if (near.size() < 6) continue;
            Vec3 mean(0, 0, 0);
            double weight = 0.0;
            for (const auto q : near) {
                mean += s.points[q] * s.areas[q];
                weight += s.areas[q];
            }
            if (weight <= 0.0) continue;
            const double score = OpenMesh::dot(s.points[v] - mean / weight, n) / r;
            if (score > bestScore) {
                bestScore = score;
                bestScale = r;
                nose = v;
            }
        }
    }
    if (nose < 0 || bestScore < 0.08) {
        out.notes.push_back("geometry: no nose tip stands out near the symmetry plane");
        return out;
    }
    Vec3 noseTip = s.points[static_cast<std::size_t>(nose)];
    const double size = bestScale; // about the nose's size: the unit of the plausibility tests below

    // 3. Forward: the face's average outward normal around the nose, in the symmetry plane.
    Vec3 forward(0, 0, 0);
    index.within(noseTip, 2.5 * size, near);
    for (const auto q : near) {
        Vec3 n = s.normals[q];
        if (OpenMesh::dot(n, s.points[q] - centroid) < 0) n = -n;
        forward += n * s.areas[q];
    }
    forward -= plane.normal * OpenMesh::dot(forward, plane.normal);
    if (forward.norm() < 1e-12) return out;
    forward.normalize();
    // The tip itself: the protrusion score is nearly flat over a rounded tip, so its maximum wanders
    // with how the mesh is cut and posed; the most forward point near it on the symmetry plane (the
    // pronasale) does not.
    index.within(noseTip, 0.6 * size, near);
    for (const auto q : near) {
        if (std::abs(plane.signedDistance(s.points[q])) > 0.1 * size) continue;
        if (OpenMesh::dot(s.points[q] - noseTip, forward) > 0.0) {
            nose = q;
            noseTip = s.points[q];
        }
    }
    const Vec3 along = OpenMesh::cross(forward, plane.normal).normalized(); // up or down

    // The nose's profile: the bridge (up) falls off slowly, the underside (down) fast.
    double frontAt[2] = {-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max()};
    for (const auto v : outside) {
        const Vec3 d = s.points[v] - noseTip;
        if (std::abs(plane.signedDistance(s.points[v])) > 0.2 * size) continue;
        const double t = OpenMesh::dot(d, along);
        if (std::abs(t) < 0.6 * size || std::abs(t) > 1.0 * size) continue;
        double& front = frontAt[t > 0 ? 0 : 1];
        front = std::max(front, OpenMesh::dot(d, forward));
    }
    const double profileCue = frontAt[0] - frontAt[1]; // > 0: `along` is up

    // The face's surface: the outside islands' triangles connected to the nose.
    std::vector<std::vector<std::uint32_t>> trianglesAt(s.points.size());
    for (std::uint32_t t = 0; t < s.triangles.size(); ++t)
        if (outsideIsland[mesh.island[t]])
            for (const auto v : s.triangles[t]) trianglesAt[v].push_back(t);
    std::vector<bool> region(s.triangles.size(), false);
    {
        std::vector<std::uint32_t> stack(trianglesAt[static_cast<std::size_t>(nose)].begin(),
                                         trianglesAt[static_cast<std::size_t>(nose)].end());
        for (const auto t : stack) region[t] = true;
        while (!stack.empty()) {
            const auto t = stack.back();
            stack.pop_back();
            for (const auto v : s.triangles[t])
                for (const auto u : trianglesAt[v])
                    if (!region[u]) {
                        region[u] = true;
                        stack.push_back(u);
                    }
        }
    }
    // Openings are looked for on the nose's own island first (things attached to the face, such as
    // eyelashes or a mouth socket, close them in the whole surface), then on the whole face surface.
    std::uint32_t noseIsland = 0;
    double noseIslandArea = -1.0;
    for (const auto t : trianglesAt[static_cast<std::size_t>(nose)])
        if (islandArea[mesh.island[t]] > noseIslandArea) {
            noseIsland = mesh.island[t];
            noseIslandArea = islandArea[mesh.island[t]];
        }
    std::vector<Triangle> regionTriangles, islandTriangles;
    for (std::size_t t = 0; t < s.triangles.size(); ++t) {
        if (region[t]) regionTriangles.push_back(s.triangles[t]);
        if (mesh.island[t] == noseIsland) islandTriangles.push_back(s.triangles[t]);
    }
    auto loops = boundaryLoops(islandTriangles);
    const std::size_t islandLoops = loops.size();
    for (auto& loop : boundaryLoops(regionTriangles)) loops.push_back(std::move(loop));

    // 4. Openings, for both choices of up; the better-fitting one wins (the profile breaks ties).
    struct Choice {
        Frame frame;
        std::vector<Loop> loops;
        MouthFit mouth;
        EyeFit eyes;
        double total = 0.0;
    };
    Choice choices[2];
    for (int c = 0; c < 2; ++c) {
        Choice& ch = choices[c];
        ch.frame.origin = noseTip;
        ch.frame.forward = forward;
        ch.frame.up = c == 0 ? along : -along;
        ch.frame.right = OpenMesh::cross(ch.frame.up, ch.frame.forward);
        double longest = 0.0;
        for (const auto& loop : loops) {
            ch.loops.push_back(describeLoop(loop, s, ch.frame));
            longest = std::max(longest, ch.loops.back().perimeter);
        }
        const auto own = [&](std::size_t k) { return k < islandLoops ? 1.5 : 1.0; };
        for (std::size_t k = 0; k < ch.loops.size(); ++k) {
            if (ch.loops[k].local.size() < 6 || ch.loops[k].perimeter >= longest)
                continue; // the outer border
            const double m = mouthScore(ch.loops[k], size) * own(k);
            if (m > ch.mouth.score) ch.mouth = {m, k};
            for (std::size_t j = 0; j < ch.loops.size(); ++j) {
                if (j == k || ch.loops[j].local.size() < 6 || ch.loops[j].perimeter >= longest) continue;
                const double e = eyeScore(ch.loops[k], ch.loops[j], size) * std::min(own(k), own(j));
                if (e > ch.eyes.score) ch.eyes = {e, k, j};
            }
        }
        ch.total =
            ch.mouth.score + 2.0 * ch.eyes.score + (c == 0 ? 1.0 : -1.0) * (profileCue > 0 ? 0.3 : -0.3);
    }
    const Choice& best = choices[0].total >= choices[1].total ? choices[0] : choices[1];
    if (std::getenv("VL_DEBUG"))
        std::fprintf(stderr, "profileCue %g totals %g %g up %g %g %g fwd %g %g %g size %g\n", profileCue,
                     choices[0].total, choices[1].total, best.frame.up[0], best.frame.up[1], best.frame.up[2],
                     forward[0], forward[1], forward[2], size);
    const Frame& frame = best.frame;
    const double orientationConfidence =
        std::clamp(std::abs(choices[0].total - choices[1].total) / 1.0, 0.3, 1.0) *
        (0.5 + 0.5 * symmetryConfidence);
    out.notes.push_back("geometry: nose tip at (" + std::to_string(noseTip[0]) + ", " +
                        std::to_string(noseTip[1]) + ", " + std::to_string(noseTip[2]) + ")");

    Surfaces regionMask;
    regionMask.region.assign(mesh.triangles.size(), false);
    regionMask.island.assign(mesh.triangles.size(), false);
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        regionMask.region[t] = region[t];
        regionMask.island[t] = mesh.island[t] == noseIsland;
    }
    regionMask.tolerance = 0.05 * size;
    FaceLandmarks& lm = out.landmarks;
    lm[Landmark::NoseTip] = fromPoint(mesh, regionMask, noseTip,
                                      std::min(0.95, 0.5 + bestScore) * (0.6 + 0.4 * symmetryConfidence),
                                      "most prominent point on the symmetry plane");

    if (best.mouth.score > 0.0) {
        const Loop& m = best.loops[best.mouth.loop];
        const double conf = std::clamp(0.55 + 0.2 * best.mouth.score, 0.55, 0.92) * orientationConfidence;
        const auto extreme = [&](bool right) {
            Vec3 e = m.local.front();
            for (const auto& p : m.local)
                if (right ? p[0] < e[0] : p[0] > e[0]) e = p;
            return e;
        };
        const Vec3 cr = extreme(true), cl = extreme(false);
        const std::string what =
            "mouth opening (boundary loop of " + std::to_string(m.local.size()) + " vertices)";
        lm[Landmark::MouthCornerRight] =
            fromPoint(mesh, regionMask, frame.world(cr), conf, what + ", right end");
        lm[Landmark::MouthCornerLeft] =
            fromPoint(mesh, regionMask, frame.world(cl), conf, what + ", left end");
        const auto upperLower = [&](double x, Landmark upper, Landmark lower, const char* where) {
            auto cuts = crossings(m, x);
            if (cuts.size() < 2) return;
            std::sort(cuts.begin(), cuts.end(), [](const Vec3& a, const Vec3& b) { return a[1] < b[1]; });
            lm[upper] =
                fromPoint(mesh, regionMask, frame.world(cuts.back()), conf, what + ", upper lip " + where);
            lm[lower] =
                fromPoint(mesh, regionMask, frame.world(cuts.front()), conf, what + ", lower lip " + where);
        };
        const double middle = 0.5 * (cr[0] + cl[0]);
        upperLower(middle, Landmark::UpperLipMid, Landmark::LowerLipMid, "middle");
        upperLower(0.5 * (cr[0] + middle), Landmark::UpperLipRight, Landmark::LowerLipRight, "right quarter");
        upperLower(0.5 * (cl[0] + middle), Landmark::UpperLipLeft, Landmark::LowerLipLeft, "left quarter");
    }
    if (best.eyes.score > 0.0) {
        const double conf = std::clamp(0.5 + 0.4 * best.eyes.score, 0.5, 0.92) * orientationConfidence;
        for (const bool right : {true, false}) {
            const Loop& e = best.loops[right ? best.eyes.right : best.eyes.left];
            Vec3 inner = e.local.front(), outer = inner;
            for (const auto& p : e.local) {
                if (std::abs(p[0]) < std::abs(inner[0])) inner = p;
                if (std::abs(p[0]) > std::abs(outer[0])) outer = p;
            }
            const std::string what = std::string(right ? "right" : "left") +
                                     " eye opening (boundary loop of " + std::to_string(e.local.size()) +
                                     " vertices)";
            lm[right ? Landmark::EyeInnerRight : Landmark::EyeInnerLeft] =
                fromPoint(mesh, regionMask, frame.world(inner), conf, what + ", inner end");
            lm[right ? Landmark::EyeOuterRight : Landmark::EyeOuterLeft] =
                fromPoint(mesh, regionMask, frame.world(outer), conf, what + ", outer end");
        }
    }

    // 5. A closed mouth: the groove between the lips on the profile below the nose, then sideways.
    const Section section(s, regionTriangles, frame);
    if (!lm[Landmark::MouthCornerRight].found()) {
        const auto groove = section.groove(0.0, -0.15 * size, -3.5 * size, size);
        if (groove) {
            // Follow the groove sideways, each step looking near the height of the last.
            const auto follow = [&](double sign) {
                Vec3 last = *groove;
                for (double x = 0.1 * size; x < 2.5 * size; x += 0.08 * size) {
                    const auto g =
                        section.groove(sign * x, last[1] + 0.3 * size, last[1] - 0.3 * size, size, last[1]);
                    if (!g) break;
                    last = *g;
                }
                return last;
            };
            const Vec3 cr = follow(-1.0), cl = follow(1.0);
            const double conf = 0.5 * orientationConfidence;
            const std::string what = "groove between the lips (closed mouth)";
            lm[Landmark::MouthCornerRight] =
                fromPoint(mesh, regionMask, frame.world(cr), conf, what + ", right end");
            lm[Landmark::MouthCornerLeft] =
                fromPoint(mesh, regionMask, frame.world(cl), conf, what + ", left end");
            lm[Landmark::UpperLipMid] =
                fromPoint(mesh, regionMask, frame.world(*groove), conf, what + ", middle");
            lm[Landmark::LowerLipMid] = lm[Landmark::UpperLipMid];
            out.notes.push_back("geometry: no mouth opening; the lips' groove followed sideways");
        }
    }

    // 6. Closed eyes (no openings): the eye sockets on the face's front, above the nose tip.
    static const auto bundledPositions = baseLandmarkPositions(makeBundledFace());
    const FaceFrame& bundled = bundledFaceFrame();
    const auto bundledLocal = [&](Landmark l) {
        const Vec3 d = bundledPositions[static_cast<std::size_t>(l)] -
                       bundledPositions[static_cast<std::size_t>(Landmark::NoseTip)];
        return Vec3(OpenMesh::dot(d, bundled.right), OpenMesh::dot(d, bundled.up),
                    OpenMesh::dot(d, bundled.forward));
    };
    const auto middle = [&](Landmark a, Landmark b, bool user) {
        return user ? (frame.local(lm[a].position) + frame.local(lm[b].position)) * 0.5
                    : (bundledLocal(a) + bundledLocal(b)) * 0.5;
    };
    const bool mouthFound = lm[Landmark::MouthCornerRight].found() && lm[Landmark::MouthCornerLeft].found();
    if (mouthFound && !lm[Landmark::EyeInnerRight].found()) {
        std::vector<std::array<Vec3, 3>> front;
        front.reserve(regionTriangles.size());
        for (const auto& t : regionTriangles)
            front.push_back(
                {frame.local(s.points[t[0]]), frame.local(s.points[t[1]]), frame.local(s.points[t[2]])});
        const double mouthDepth = -middle(Landmark::MouthCornerRight, Landmark::MouthCornerLeft, true)[1];
        const double mouthWidth =
            (lm[Landmark::MouthCornerLeft].position - lm[Landmark::MouthCornerRight].position).norm();
        const ClosedEyes eyes = findClosedEyes(front, mouthDepth, mouthWidth);
        if (eyes.found) {
            const double conf = eyes.confidence * orientationConfidence;
            for (const int side : {0, 1}) {
                const bool right = side == 0;
                const std::string what = std::string(right ? "right " : "left ") + eyes.method;
                lm[right ? Landmark::EyeInnerRight : Landmark::EyeInnerLeft] =
                    fromPoint(mesh, regionMask, frame.world(eyes.inner[side]), conf, what + ", inner corner");
                lm[right ? Landmark::EyeOuterRight : Landmark::EyeOuterLeft] =
                    fromPoint(mesh, regionMask, frame.world(eyes.outer[side]), conf, what + ", outer corner");
            }
            out.notes.push_back("geometry: no eye openings; the eyes placed in the eye sockets");
        }
    }

    // 7. Whatever is missing, from the bundled face's proportions: offsets from the nose tip in the
    // face's frame, scaled by the nose-to-mouth (or nose-to-eyes) distance, projected onto the surface.
    double scale = 0.0;
    if (lm[Landmark::MouthCornerRight].found() && lm[Landmark::MouthCornerLeft].found())
        scale = middle(Landmark::MouthCornerRight, Landmark::MouthCornerLeft, true)[1] /
                middle(Landmark::MouthCornerRight, Landmark::MouthCornerLeft, false)[1];
    else if (lm[Landmark::EyeInnerRight].found() && lm[Landmark::EyeInnerLeft].found())
        scale = middle(Landmark::EyeInnerRight, Landmark::EyeInnerLeft, true)[1] /
                middle(Landmark::EyeInnerRight, Landmark::EyeInnerLeft, false)[1];
    if (scale > 0.0)
        for (const auto l : allLandmarks()) {
            if (lm[l].found() || !isRequired(l)) continue; // optional lip points only from an opening
            const Vec3 guess = frame.world(bundledLocal(l) * scale);
            lm[l] = fromPoint(mesh, regionMask, guess, 0.25, "estimated from the face's proportions",
                              LandmarkSource::Estimate);
        }
    refineEstimatedEyes(s, outside, centroid, frame, mesh, regionMask, lm);
    return out;
}

} // namespace vl::face
