#include "core/face/MouthMeasures.h"

#include "core/common/Error.h"
#include "core/face/FaceDomain.h"
#include "core/face/Landmarks.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace vl::face {

namespace {

// The skin vertex at a landmark's (u,v) (coordinates in files are rounded: a small tolerance).
std::size_t landmarkVertex(const MeshData& head, Landmark landmark, std::string_view where) {
    const Vec2 at = canonicalPosition(landmark);
    std::size_t best = 0;
    double bestDistance = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < head.uvs.size(); ++i) {
        if (headTileOf(head.uvs[i][0]) != HeadTile::Skin) continue;
        const double d = (head.uvs[i] - at).norm();
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    if (bestDistance > 1e-5)
        throwInputError(where, "no skin vertex at the " + std::string(toString(landmark)) + " (u,v) (" +
                                   std::to_string(at[0]) + ", " + std::to_string(at[1]) +
                                   "): expected a mesh of the face domain, as `visemelab visemes` writes");
    return best;
}

enum Label : std::uint8_t { Other = 0, UpperTeeth = 1, LowerTeeth = 2, Tongue = 3 };

// Per triangle: which part it shows. The teeth tile holds two rows, told apart as the two connected
// pieces of it, the upper row higher.
std::vector<Label> triangleLabels(const MeshData& head, std::string_view where) {
    const std::size_t n = head.positions.size();
    std::vector<std::uint32_t> parent(n);
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    const auto tileOf = [&](const Triangle& t) { return headTileOf(head.uvs[t[0]][0]); };
    for (const auto& t : head.triangles)
        if (tileOf(t) == HeadTile::Teeth)
            for (int k = 1; k < 3; ++k) parent[find(t[k])] = find(t[0]);
    // Mean height of each piece of the teeth tile.
    std::vector<std::uint32_t> roots;
    std::vector<double> sumY, count;
    for (std::size_t i = 0; i < n; ++i) {
        if (headTileOf(head.uvs[i][0]) != HeadTile::Teeth) continue;
        const auto r = find(static_cast<std::uint32_t>(i));
        auto it = std::find(roots.begin(), roots.end(), r);
        if (it == roots.end()) {
            if (roots.size() == 2)
                throwInputError(where,
                                "the teeth are more than two separate rows: not a bundled head's teeth");
            roots.push_back(r);
            sumY.push_back(0.0);
            count.push_back(0.0);
            it = roots.end() - 1;
        }
        const auto k = static_cast<std::size_t>(it - roots.begin());
        sumY[k] += head.positions[i][1];
        count[k] += 1.0;
    }
    if (roots.size() == 1)
        throwInputError(where, "the teeth are one piece: expected an upper and a lower row");
    const std::uint32_t upperRoot =
        roots.empty() ? 0u : (sumY[0] / count[0] >= sumY[1] / count[1] ? roots[0] : roots[1]);
    std::vector<Label> labels(head.triangles.size(), Other);
    for (std::size_t f = 0; f < head.triangles.size(); ++f) {
        const auto& t = head.triangles[f];
        if (tileOf(t) == HeadTile::Teeth)
            labels[f] = find(t[0]) == upperRoot ? UpperTeeth : LowerTeeth;
        else if (tileOf(t) == HeadTile::Tongue)
            labels[f] = Tongue;
    }
    return labels;
}

// Areas of the teeth and tongue seen from the front (+z) inside the box [lo, hi] of the (x, y) plane:
// an orthographic z-buffer of every triangle, the nearest surface wins.
void seenAreas(const MeshData& head, const std::vector<Label>& labels, const Vec2& lo, const Vec2& hi,
               double pixel, MouthMeasures& m) {
    const int w = std::max(1, static_cast<int>(std::ceil((hi[0] - lo[0]) / pixel)));
    const int h = std::max(1, static_cast<int>(std::ceil((hi[1] - lo[1]) / pixel)));
    std::vector<double> depth(static_cast<std::size_t>(w) * h, -std::numeric_limits<double>::max());
    std::vector<Label> seen(depth.size(), Other);
    for (std::size_t f = 0; f < head.triangles.size(); ++f) {
        const auto& t = head.triangles[f];
        const Vec3 &a = head.positions[t[0]], &b = head.positions[t[1]], &c = head.positions[t[2]];
        const double area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        if (area == 0.0) continue; // seen edge-on
        const auto column = [&](double x) { return (x - lo[0]) / pixel; };
        const auto row = [&](double y) { return (y - lo[1]) / pixel; };
        const int x0 = std::max(0, static_cast<int>(std::floor(column(std::min({a[0], b[0], c[0]})))));
        const int x1 = std::min(w - 1, static_cast<int>(std::ceil(column(std::max({a[0], b[0], c[0]})))));
        const int y0 = std::max(0, static_cast<int>(std::floor(row(std::min({a[1], b[1], c[1]})))));
        const int y1 = std::min(h - 1, static_cast<int>(std::ceil(row(std::max({a[1], b[1], c[1]})))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const double px = lo[0] + (x + 0.5) * pixel, py = lo[1] + (y + 0.5) * pixel;
                const double wa = ((b[0] - px) * (c[1] - py) - (c[0] - px) * (b[1] - py)) / area;
                const double wb = ((c[0] - px) * (a[1] - py) - (a[0] - px) * (c[1] - py)) / area;
                const double wc = 1.0 - wa - wb;
                if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
                const double z = wa * a[2] + wb * b[2] + wc * c[2];
                const std::size_t p = static_cast<std::size_t>(y) * w + x;
                if (z <= depth[p]) continue;
                depth[p] = z;
                seen[p] = labels[f];
            }
    }
    const double pixelArea = pixel * pixel;
    for (const Label l : seen) {
        if (l == UpperTeeth) m.upperTeethSeen += pixelArea;
        if (l == LowerTeeth) m.lowerTeethSeen += pixelArea;
        if (l == Tongue) m.tongueSeen += pixelArea;
    }
}

// The inner lip contour seen from the front: the skin's boundary round the mouth hole, split into the
// upper and the lower rim (each from corner to corner, in (x, y)), and the opening's height between
// them at fractions of the way from the middle to the corners.
void measureOpeningProfile(const MeshData& head, std::string_view where, MouthMeasures& m) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    for (const auto& t : head.triangles) {
        if (headTileOf(head.uvs[t[0]][0]) != HeadTile::Skin) continue;
        for (int k = 0; k < 3; ++k)
            edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    }
    std::sort(edges.begin(), edges.end());
    const auto nearHole = [&](std::uint32_t v) {
        const Vec2& uv = head.uvs[v];
        return std::abs(uv[0] - kMouthU) <= kMouthHalfWidth + 1e-6 &&
               std::abs(uv[1] - kMouthV) <= kMouthHalfHeight + 1e-6;
    };
    // Boundary edges (in one triangle only) round the hole: their vertices, by rim.
    std::vector<std::uint32_t> upper, lower;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const bool single =
            (k == 0 || edges[k - 1] != edges[k]) && (k + 1 == edges.size() || edges[k + 1] != edges[k]);
        if (!single || !nearHole(edges[k].first) || !nearHole(edges[k].second)) continue;
        for (const auto v : {edges[k].first, edges[k].second}) {
            const double dv = head.uvs[v][1] - kMouthV;
            if (dv >= -1e-6) upper.push_back(v); // the corners (dv = 0) are on both rims
            if (dv <= 1e-6) lower.push_back(v);
        }
    }
    const auto byU = [&](std::vector<std::uint32_t>& rim) {
        std::sort(rim.begin(), rim.end());
        rim.erase(std::unique(rim.begin(), rim.end()), rim.end());
        std::sort(rim.begin(), rim.end(), [&](auto a, auto b) { return head.uvs[a][0] < head.uvs[b][0]; });
        if (rim.size() < 2)
            throwInputError(where, "the mouth hole has no rim: expected a mesh of the face domain");
    };
    byU(upper);
    byU(lower);
    // The rim's height at x: where the rim crosses x (the lowest crossing of the upper rim, the
    // highest of the lower one: the opening's edge).
    const auto heightAt = [&](const std::vector<std::uint32_t>& rim, double x, bool isUpper) {
        double best = isUpper ? std::numeric_limits<double>::max() : -std::numeric_limits<double>::max();
        for (std::size_t k = 0; k + 1 < rim.size(); ++k) {
            const Vec3 &a = head.positions[rim[k]], &b = head.positions[rim[k + 1]];
            if ((x < a[0] && x < b[0]) || (x > a[0] && x > b[0])) continue;
            const double s = a[0] == b[0] ? 0.5 : (x - a[0]) / (b[0] - a[0]);
            const double y = a[1] + s * (b[1] - a[1]);
            best = isUpper ? std::min(best, y) : std::max(best, y);
        }
        return best;
    };
    const double middle = 0.5 * (m.cornerLeft[0] + m.cornerRight[0]);
    const double half = 0.5 * (m.cornerLeft[0] - m.cornerRight[0]);
    for (std::size_t k = 0; k < kOpeningProfileAt.size(); ++k) {
        double sum = 0.0;
        for (const double side : {-1.0, 1.0}) {
            const double x = middle + side * kOpeningProfileAt[k] * half;
            sum += heightAt(upper, x, true) - heightAt(lower, x, false);
        }
        m.openingProfile[k] = 0.5 * sum;
    }
}

} // namespace

MouthMeasures measureMouth(const MeshData& head, std::string_view where) {
    if (!head.hasUVs() || head.uvs.size() != head.positions.size())
        throwInputError(where, "the mesh has no (u,v): expected a mesh of the face domain");
    for (const auto& t : head.triangles)
        for (const auto v : t)
            if (v >= head.positions.size()) throwInputError(where, "a triangle's vertex is out of range");
    MouthMeasures m;
    const auto at = [&](Landmark l) { return head.positions[landmarkVertex(head, l, where)]; };
    m.cornerRight = at(Landmark::MouthCornerRight);
    m.cornerLeft = at(Landmark::MouthCornerLeft);
    m.upperLip = at(Landmark::UpperLipMid);
    m.lowerLip = at(Landmark::LowerLipMid);
    m.opening = m.upperLip[1] - m.lowerLip[1];
    m.lipDistance = (m.upperLip - m.lowerLip).norm();
    m.width = (m.cornerLeft - m.cornerRight).norm();
    measureOpeningProfile(head, where, m);

    // The lips' outer surfaces near the midline: the bands of the face domain above and below the
    // mouth line that the lips cover.
    const double band = 2.5 * kMouthHalfHeight, midline = 0.15 * kMouthHalfWidth;
    m.upperLipFront = m.upperLip[2];
    m.lowerLipFront = m.lowerLip[2];
    std::vector<std::size_t> lowerLipVertices;
    for (std::size_t i = 0; i < head.uvs.size(); ++i) {
        const Vec2& uv = head.uvs[i];
        if (headTileOf(uv[0]) != HeadTile::Skin || std::abs(uv[0] - kMouthU) > midline) continue;
        const double dv = uv[1] - kMouthV;
        if (dv > 0.0 && dv <= band) m.upperLipFront = std::max(m.upperLipFront, head.positions[i][2]);
        if (dv < 0.0 && dv >= -band) {
            m.lowerLipFront = std::max(m.lowerLipFront, head.positions[i][2]);
            lowerLipVertices.push_back(i);
        }
    }

    const std::vector<Label> labels = triangleLabels(head, where);
    // The central incisors of each row: the vertices in the middle third of the row's width.
    std::vector<std::vector<std::size_t>> incisors(3);
    for (const Label row : {UpperTeeth, LowerTeeth}) {
        std::vector<char> in(head.positions.size(), 0);
        double lo = std::numeric_limits<double>::max(), hi = -lo;
        for (std::size_t f = 0; f < head.triangles.size(); ++f)
            if (labels[f] == row)
                for (const auto v : head.triangles[f]) {
                    in[v] = 1;
                    lo = std::min(lo, head.positions[v][0]);
                    hi = std::max(hi, head.positions[v][0]);
                }
        for (std::size_t i = 0; i < in.size(); ++i)
            if (in[i] && std::abs(head.positions[i][0] - 0.5 * (lo + hi)) <= (hi - lo) / 6.0)
                incisors[row].push_back(i);
    }
    if (!incisors[UpperTeeth].empty() && !incisors[LowerTeeth].empty()) {
        // Labiodental contact: the lower lip near the midline to the upper incisors.
        double nearest = std::numeric_limits<double>::max(), upperEdge = nearest, lowerEdge = -nearest;
        double upperFront = -nearest;
        for (const auto i : incisors[UpperTeeth]) {
            const Vec3& p = head.positions[i];
            for (const auto l : lowerLipVertices) nearest = std::min(nearest, (p - head.positions[l]).norm());
            upperEdge = std::min(upperEdge, p[1]);
            upperFront = std::max(upperFront, p[2]);
        }
        for (const auto i : incisors[LowerTeeth]) lowerEdge = std::max(lowerEdge, head.positions[i][1]);
        if (!lowerLipVertices.empty()) m.lowerLipToUpperTeeth = nearest;
        m.teethGap = upperEdge - lowerEdge;
        // The tongue's foremost point against the upper incisors' front.
        double tongueFront = -std::numeric_limits<double>::max();
        for (std::size_t f = 0; f < head.triangles.size(); ++f)
            if (labels[f] == Tongue)
                for (const auto v : head.triangles[f])
                    tongueFront = std::max(tongueFront, head.positions[v][2]);
        if (tongueFront > -std::numeric_limits<double>::max()) m.tongueAhead = tongueFront - upperFront;
    }

    // The front view of the mouth: the box of its landmarks with a margin of a fifth of its width.
    const double margin = 0.2 * std::max(m.width, 1e-9);
    const Vec2 lo(std::min({m.cornerRight[0], m.cornerLeft[0], m.upperLip[0], m.lowerLip[0]}) - margin,
                  std::min({m.cornerRight[1], m.cornerLeft[1], m.upperLip[1], m.lowerLip[1]}) - margin);
    const Vec2 hi(std::max({m.cornerRight[0], m.cornerLeft[0], m.upperLip[0], m.lowerLip[0]}) + margin,
                  std::max({m.cornerRight[1], m.cornerLeft[1], m.upperLip[1], m.lowerLip[1]}) + margin);
    seenAreas(head, labels, lo, hi, kMouthPixelPerWidth * std::max(m.width, 1e-9), m);
    return m;
}

} // namespace vl::face
