#include "core/face/FaceBuild.h"

#include "core/common/Error.h"
#include "core/face/BundledFace.h"
#include "core/face/FaceDomain.h"
#include "core/face/FaceShape.h" // the eye opening's lens, shared with the bundled face
#include "core/face/HeadParts.h"
#include "core/face/MeshGeometry.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <set>

namespace vl::face {

namespace {

// Coarse occupancy of a set of islands in texture space, to tell whether another island overlaps them.
class UvOccupancy {
  public:
    UvOccupancy(const UvMesh& m, const std::vector<bool>& islands) {
        bool any = false;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) {
            if (!islands[m.island[t]]) continue;
            for (int k = 0; k < 3; ++k) {
                const Vec2& q = m.texCoords[m.texTriangles[t][k]];
                if (!any) lo_ = hi_ = q;
                any = true;
                lo_.minimize(q);
                hi_.maximize(q);
            }
        }
        cells_.assign(kSize * kSize, false);
        if (!any) return;
        for (std::size_t t = 0; t < m.triangles.size(); ++t) {
            if (!islands[m.island[t]]) continue;
            // Mark the cells of the triangle's (u,v) bounding box sampled densely enough for thin ones.
            const auto& tex = m.texTriangles[t];
            const Vec2 &a = m.texCoords[tex[0]], &b = m.texCoords[tex[1]], &c = m.texCoords[tex[2]];
            for (int i = 0; i <= 4; ++i)
                for (int j = 0; i + j <= 4; ++j) mark(a + (b - a) * (i / 4.0) + (c - a) * (j / 4.0));
        }
    }
    bool occupied(const Vec2& p) const {
        const int i = cellX(p), j = cellY(p);
        return i >= 0 && j >= 0 && i < kSize && j < kSize && cells_[static_cast<std::size_t>(j) * kSize + i];
    }

  private:
    static constexpr int kSize = 256;
    int cellX(const Vec2& p) const {
        return static_cast<int>((p[0] - lo_[0]) / std::max(hi_[0] - lo_[0], 1e-12) * kSize);
    }
    int cellY(const Vec2& p) const {
        return static_cast<int>((p[1] - lo_[1]) / std::max(hi_[1] - lo_[1], 1e-12) * kSize);
    }
    void mark(const Vec2& p) {
        const int i = std::clamp(cellX(p), 0, kSize - 1), j = std::clamp(cellY(p), 0, kSize - 1);
        cells_[static_cast<std::size_t>(j) * kSize + i] = true;
    }
    Vec2 lo_{0, 0}, hi_{1, 1};
    std::vector<bool> cells_;
};

enum class SampleState : std::uint8_t { Sampled, Hole, Outside };

// Calls visit(t) for each 4-neighbour t of sample s on an n x n grid (row-major).
template <class Visit> void forEachGridNeighbour(int s, int n, Visit visit) {
    const int i = s % n, j = s / n;
    if (i + 1 < n) visit(s + 1);
    if (i > 0) visit(s - 1);
    if (j + 1 < n) visit(s + n);
    if (j > 0) visit(s - n);
}

// Laplace (membrane) filling of the unknown samples with the sampled ones as boundary values: each
// unknown becomes the average of its grid neighbours. Unknowns start at the nearest known value
// (breadth-first), then successive over-relaxation smooths them.
void fillUnknown(std::vector<Vec3>& samples, const std::vector<SampleState>& state, int n) {
    std::vector<int> order;
    std::vector<bool> known(samples.size());
    std::deque<int> queue;
    for (std::size_t s = 0; s < samples.size(); ++s) {
        known[s] = state[s] == SampleState::Sampled;
        if (known[s]) queue.push_back(static_cast<int>(s));
    }
    if (queue.empty()) return;
    std::vector<bool> reached = known;
    while (!queue.empty()) {
        const int s = queue.front();
        queue.pop_front();
        forEachGridNeighbour(s, n, [&](int t) {
            if (reached[t]) return;
            reached[t] = true;
            samples[t] = samples[s];
            order.push_back(t);
            queue.push_back(t);
        });
    }
    if (order.empty()) return;
    constexpr double kOmega = 1.85;
    for (int iteration = 0; iteration < 4000; ++iteration) {
        double change = 0.0, size = 0.0;
        for (const int s : order) {
            Vec3 sum(0, 0, 0);
            int count = 0;
            forEachGridNeighbour(s, n, [&](int t) {
                sum += samples[t];
                ++count;
            });
            const Vec3 next = samples[s] + (sum / count - samples[s]) * kOmega;
            change = std::max(change, (next - samples[s]).norm());
            size = std::max(size, next.norm());
            samples[s] = next;
        }
        if (change <= 1e-9 * std::max(size, 1.0)) break;
    }
}

// Grid distance (4-neighbour steps) from each sample of `region` to the nearest sample outside it.
std::vector<int> distanceInside(const std::vector<bool>& region, int n) {
    std::vector<int> distance(region.size(), -1);
    std::deque<int> queue;
    for (std::size_t s = 0; s < region.size(); ++s)
        if (!region[s]) {
            distance[s] = 0;
            queue.push_back(static_cast<int>(s));
        }
    while (!queue.empty()) {
        const int s = queue.front();
        queue.pop_front();
        forEachGridNeighbour(s, n, [&](int t) {
            if (distance[t] >= 0) return;
            distance[t] = distance[s] + 1;
            queue.push_back(t);
        });
    }
    return distance;
}

// Rounds to a step of about a micrometre on a human-sized face, as a decimal so the project file
// prints short numbers.
double roundTo(double x, double inverseStep) {
    return std::round(x * inverseStep) / inverseStep;
}

} // namespace

std::vector<IslandUse> chooseFaceIslands(const UvMesh& m, const FaceLandmarks& landmarks) {
    const auto described = describeIslands(m);
    std::vector<IslandUse> islands(described.size());
    for (std::size_t k = 0; k < described.size(); ++k) islands[k].island = described[k];
    std::vector<bool> face(islands.size(), false);
    for (const auto& l : landmarks.at)
        if (l.found() && l.island >= 0 && static_cast<std::size_t>(l.island) < islands.size()) {
            islands[static_cast<std::size_t>(l.island)].landmarks += 1;
            face[static_cast<std::size_t>(l.island)] = true;
        }
    for (std::size_t k = 0; k < islands.size(); ++k)
        if (face[k]) {
            islands[k].used = true;
            islands[k].reason = "holds " + std::to_string(islands[k].landmarks) + " landmark(s)";
        }
    // Islands sharing a vertex with the face islands continue the face across a UV seam, unless they
    // overlap it in (u,v) (then sampling could not tell them apart).
    const auto weld = weldedVertexIds(m.positions);
    std::set<std::uint32_t> faceVertices;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        if (face[m.island[t]])
            for (const auto v : m.triangles[t]) faceVertices.insert(weld[v]);
    std::vector<bool> adjacent(islands.size(), false);
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        if (!face[m.island[t]])
            for (const auto v : m.triangles[t])
                if (faceVertices.count(weld[v])) adjacent[m.island[t]] = true;
    const UvOccupancy occupancy(m, face);
    std::vector<std::size_t> inside(islands.size(), 0), total(islands.size(), 0);
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const auto is = m.island[t];
        if (!adjacent[is]) continue;
        const auto& tex = m.texTriangles[t];
        const Vec2 centroid = (m.texCoords[tex[0]] + m.texCoords[tex[1]] + m.texCoords[tex[2]]) / 3.0;
        total[is] += 1;
        inside[is] += occupancy.occupied(centroid);
    }
    for (std::size_t k = 0; k < islands.size(); ++k) {
        if (face[k]) continue;
        if (!adjacent[k]) {
            islands[k].reason = "not joined to the face";
        } else if (inside[k] * 10 > total[k]) {
            islands[k].reason = "joined to the face but overlapping it in (u,v)";
        } else {
            islands[k].used = true;
            islands[k].reason = "continues the face across a UV seam";
        }
    }
    return islands;
}

DeformationCascade retargetedCascade(const SampledField& base, const FaceFrame& frame, double scale,
                                     std::string name) {
    DeformationCascade cascade = makeBundledFace();
    cascade.name = std::move(name);
    for (auto& stage : cascade.stages) {
        if (stage.kind == StageKind::Constant) {
            stage.field = VectorField{};
            stage.field.sampled = base;
            continue;
        }
        for (auto& region : stage.field.influences) {
            region.direction = frame.rotate(region.direction);
            region.magnitude *= scale;
        }
        for (auto& sample : stage.field.sampled.samples) sample = frame.rotate(sample) * scale;
    }
    return cascade;
}

namespace {

// The eyes open as the bundled face's do: a mesh with closed eyes (or a slit between the lids) would
// show none of the eyeballs (issue 32). Inside each eye's opening, the bundled face's lens between the
// corners in the domain (the alignment puts the user's corners there), the skin turns back behind
// the carried eyeball (where makeHeadParts puts it) into the socket, as the bundled face's does
// (core/face/FaceGeometry.cpp): first to the eyeball's front (ramped in from the lid margin), then
// deeper towards the axis by the bundled socket's profile, scaled to the face. Where the alignment
// maps the lens onto less height than the bundled face's proportion of the eye's width (a face whose
// (u,v) crowd the eyes), the lens is taller in the domain so that the opening keeps that proportion.
double lensHeight(const std::vector<Vec3>& samples, int n, double u, const Vec3& up) {
    const auto at = [&](double v) { // bilinear in the geometry image
        const double x = u * (n - 1), y = std::clamp(v, 0.0, 1.0) * (n - 1);
        const int i = std::min(static_cast<int>(x), n - 2), j = std::min(static_cast<int>(y), n - 2);
        const double fx = x - i, fy = y - j;
        const auto s = [&](int a, int b) { return samples[static_cast<std::size_t>(b) * n + a]; };
        return (s(i, j) * (1 - fx) + s(i + 1, j) * fx) * (1 - fy) +
               (s(i, j + 1) * (1 - fx) + s(i + 1, j + 1) * fx) * fy;
    };
    const detail::EyeLens lens = detail::eyeLens(u, detail::kEyeCentreV);
    return (at(detail::kEyeCentreV + lens.upper) - at(detail::kEyeCentreV - lens.lower)) | up;
}

// The bundled face's lens height over its eye's width (computed once from its geometry).
double bundledLensProportion() {
    static const double proportion = [] {
        const DeformationCascade bundled = makeBundledFace();
        const SampledField* base = nullptr;
        for (const auto& stage : bundled.stages)
            if (stage.kind == StageKind::Constant) base = &stage.field.sampled;
        const auto landmarks = baseLandmarkPositions(bundled);
        const double width = (landmarks[static_cast<std::size_t>(Landmark::EyeOuterLeft)] -
                              landmarks[static_cast<std::size_t>(Landmark::EyeInnerLeft)])
                                 .norm();
        return lensHeight(base->samples, base->width, kMouthU + detail::kEyeCentreU, bundledFaceFrame().up) /
               width;
    }();
    return proportion;
}

void openEyes(std::vector<Vec3>& samples, int n, const std::array<Vec3, kLandmarkCount>& positions,
              const FaceFrame& frame, double scale) {
    const double radius = kEyeballRadius * scale;
    for (const bool left : {false, true}) {
        const Vec3 centre = carriedEyeballCentre(positions, left);
        const double width =
            (positions[static_cast<std::size_t>(left ? Landmark::EyeOuterLeft : Landmark::EyeOuterRight)] -
             positions[static_cast<std::size_t>(left ? Landmark::EyeInnerLeft : Landmark::EyeInnerRight)])
                .norm();
        const double height =
            lensHeight(samples, n, kMouthU + (left ? 1.0 : -1.0) * detail::kEyeCentreU, frame.up);
        // How much taller the lens is made: never shorter, at most three times (a face whose lens
        // maps onto nothing keeps a plausible eye rather than a tall hole).
        const double stretch =
            height > 0.0 ? std::clamp(bundledLensProportion() * width / height, 1.0, 3.0) : 3.0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double u = double(i) / (n - 1), v = double(j) / (n - 1);
                if ((u > kMouthU) != left) continue;
                detail::EyeLens lens = detail::eyeLens(u, v);
                lens.offset /= stretch;
                const double inside = lens.inside();
                if (inside <= 0.0) continue;
                Vec3& p = samples[static_cast<std::size_t>(j) * n + i];
                const Vec3 d = p - centre;
                const double depth = d | frame.forward;
                const double lateral = (d - frame.forward * depth).sqrnorm();
                const double front = std::sqrt(std::max(0.0, radius * radius - lateral));
                const double along = std::clamp(lens.along, -1.0, 1.0), shape = 1.0 - along * along;
                const double socket =
                    scale * std::sqrt(shape) * std::sqrt(1.0 - (1.0 - inside) * (1.0 - inside));
                // In from the lid margins, and from the corners, where the opening closes.
                const double ramp = std::min(1.0, inside / 0.05) * std::min(1.0, shape / 0.2);
                p -= frame.forward * (ramp * std::max(0.0, depth - front) + socket);
            }
    }
}

} // namespace

BuiltFace buildFace(const UvMesh& mesh, const FaceLandmarks& landmarks, const FaceBuildOptions& options) {
    if (options.gridSize < 17 || options.gridSize > 2049)
        throwInputError("face build",
                        "grid size " + std::to_string(options.gridSize) + " is outside 17..2049");
    BuiltFace built;
    built.landmarks = landmarks;
    FaceBuildReport& report = built.report;
    report.droppedTriangles = mesh.droppedTriangles;
    report.islands = chooseFaceIslands(mesh, landmarks);

    // Face islands first (most landmarks first), then the ones across seams (largest first).
    std::vector<std::uint32_t> order;
    for (std::uint32_t k = 0; k < report.islands.size(); ++k)
        if (report.islands[k].used) order.push_back(k);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const auto &x = report.islands[a], &y = report.islands[b];
        if (x.landmarks != y.landmarks) return x.landmarks > y.landmarks;
        return x.island.area > y.island.area;
    });
    const UvLocator locator(mesh, order, 1e-6);
    const FaceAlignment alignment(mesh, locator, landmarks);
    report.holes = alignment.holes();
    report.domainCoverage = alignment.domainCoverage();
    report.retracted = alignment.retractedFraction();
    report.closedGap = alignment.closedGap();
    report.foldedSamples = alignment.foldedSamples();

    std::array<Vec3, kLandmarkCount> positions{};
    for (const auto l : allLandmarks()) positions[static_cast<std::size_t>(l)] = landmarks[l].position;
    report.frame = frameFromLandmarks(positions);
    report.scale = report.frame.scaleTo(bundledFaceFrame());

    // The geometry image.
    const int n = options.gridSize;
    std::vector<Vec3> samples(static_cast<std::size_t>(n) * n, Vec3(0, 0, 0));
    std::vector<SampleState> state(samples.size(), SampleState::Outside);
    std::vector<int> hole(samples.size(), 0);
    tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& rows) {
        for (int j = rows.begin(); j != rows.end(); ++j)
            for (int i = 0; i < n; ++i) {
                const std::size_t s = static_cast<std::size_t>(j) * n + i;
                const Vec2 c = alignment.canonical(Vec2(double(i) / (n - 1), double(j) / (n - 1)));
                const int coverage = alignment.coverageAt(c);
                if (coverage >= 1) {
                    state[s] = SampleState::Hole;
                    hole[s] = coverage;
                    continue;
                }
                const UvHit hit = locator.locate(alignment.splineUV(c));
                if (!hit.found) continue; // outside: filled from the neighbours
                samples[s] = hit.position;
                state[s] = SampleState::Sampled;
            }
    });
    std::size_t outside = 0;
    for (const auto st : state) {
        report.filledSamples += st != SampleState::Sampled;
        outside += st == SampleState::Outside;
    }
    if (report.filledSamples == samples.size())
        throwInputError("face build",
                        "the aligned face domain does not land on the mesh: check the landmarks");
    fillUnknown(samples, state, n);

    // Eye openings become sockets: pushed back behind where the eyeballs sit, deepest in the middle.
    for (std::size_t h = 0; h < report.holes.size(); ++h) {
        const auto& role = report.holes[h].role;
        if (role != "eye_right" && role != "eye_left") continue;
        const bool right = role == "eye_right";
        const Vec3 outer =
            positions[static_cast<std::size_t>(right ? Landmark::EyeOuterRight : Landmark::EyeOuterLeft)];
        const Vec3 inner =
            positions[static_cast<std::size_t>(right ? Landmark::EyeInnerRight : Landmark::EyeInnerLeft)];
        const double depth = 0.45 * (outer - inner).norm();
        std::vector<bool> region(samples.size());
        for (std::size_t s = 0; s < samples.size(); ++s) region[s] = hole[s] == static_cast<int>(h) + 1;
        const auto distance = distanceInside(region, n);
        int deepest = 1;
        for (std::size_t s = 0; s < samples.size(); ++s)
            if (region[s]) deepest = std::max(deepest, distance[s]);
        for (std::size_t s = 0; s < samples.size(); ++s)
            if (region[s]) {
                const double t = std::min(1.0, double(distance[s]) / deepest);
                samples[s] -= report.frame.forward * (depth * std::sin(0.5 * M_PI * t));
            }
    }

    openEyes(samples, n, positions, report.frame, report.scale);

    const double inverseStep = std::pow(10.0, std::round(4.0 - std::log10(std::max(report.scale, 1e-12))));
    SampledField base;
    base.width = base.height = n;
    base.samples.reserve(samples.size());
    for (const auto& p : samples)
        base.samples.emplace_back(roundTo(p[0], inverseStep), roundTo(p[1], inverseStep),
                                  roundTo(p[2], inverseStep));
    built.cascade = retargetedCascade(base, report.frame, report.scale, options.name);

    if (report.foldedSamples > 0)
        report.warnings.push_back("the landmarks fold the alignment at " +
                                  std::to_string(report.foldedSamples) +
                                  " of 4225 test points: check them (left and right, upper and lower)");
    if (outside > samples.size() / 50)
        report.warnings.push_back(std::to_string(outside) +
                                  " geometry samples fell off the mesh and were filled in");
    if (report.domainCoverage < 0.35)
        report.warnings.push_back("the mesh covers only " + std::to_string(int(report.domainCoverage * 100)) +
                                  "% of the face domain: the outer face is stretched over what there is");
    return built;
}

} // namespace vl::face
