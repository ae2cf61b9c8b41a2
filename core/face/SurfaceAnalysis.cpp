#include "core/face/SurfaceAnalysis.h"

#include "core/face/MeshGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace vl::face {

WeldedSurface weldSurface(const UvMesh& mesh) {
    WeldedSurface s;
    const auto ids = weldedVertexIds(mesh.positions);
    std::vector<std::int64_t> point(mesh.positions.size(), -1);
    s.pointOf.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        if (point[ids[v]] < 0) {
            point[ids[v]] = static_cast<std::int64_t>(s.points.size());
            s.points.push_back(mesh.positions[v]);
        }
        s.pointOf[v] = static_cast<std::uint32_t>(point[ids[v]]);
    }
    s.normals.assign(s.points.size(), Vec3(0, 0, 0));
    s.areas.assign(s.points.size(), 0.0);
    for (const auto& t : mesh.triangles) {
        const Triangle w{s.pointOf[t[0]], s.pointOf[t[1]], s.pointOf[t[2]]};
        s.triangles.push_back(w);
        const Vec3 n = OpenMesh::cross(s.points[w[1]] - s.points[w[0]], s.points[w[2]] - s.points[w[0]]);
        for (const auto v : w) {
            s.normals[v] += n;
            s.areas[v] += n.norm() / 6.0;
        }
    }
    for (auto& n : s.normals)
        if (n.norm() > 0.0) n.normalize();
    Vec3 lo, hi;
    if (bounds(s.points, lo, hi)) s.diagonal = (hi - lo).norm();
    return s;
}

std::vector<bool> visibleTriangles(const WeldedSurface& s, int directions, int minimumResolution) {
    std::vector<bool> visible(s.triangles.size(), false);
    if (s.triangles.empty()) return visible;
    // A pixel keeps one triangle: about as many pixels as triangles, so that a dense mesh does not
    // lose most of its triangles to their neighbours in the same pixel.
    const int resolution =
        std::clamp(static_cast<int>(std::ceil(1.2 * std::sqrt(double(s.triangles.size())))),
                   minimumResolution, std::max(minimumResolution, 1200));
    Vec3 lo, hi;
    bounds(s.points, lo, hi);
    const Vec3 centre = (lo + hi) * 0.5;
    const double radius = std::max(0.5 * s.diagonal, 1e-12);
    const double pixel = 2.0 * radius / resolution;
    std::vector<double> depth(static_cast<std::size_t>(resolution) * resolution);
    std::vector<std::int64_t> id(depth.size());
    std::vector<Vec3> projected(s.points.size());
    for (int k = 0; k < directions; ++k) {
        // Fibonacci sphere: evenly spread view directions.
        const double z = 1.0 - (2.0 * k + 1.0) / directions;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = k * M_PI * (3.0 - std::sqrt(5.0));
        const Vec3 d(r * std::cos(phi), r * std::sin(phi), z);
        const Vec3 a =
            (std::abs(d[0]) < 0.9 ? OpenMesh::cross(d, Vec3(1, 0, 0)) : OpenMesh::cross(d, Vec3(0, 1, 0)))
                .normalized();
        const Vec3 b = OpenMesh::cross(d, a);
        for (std::size_t v = 0; v < s.points.size(); ++v) {
            const Vec3 q = s.points[v] - centre;
            projected[v] = Vec3((OpenMesh::dot(q, a) + radius) / pixel,
                                (OpenMesh::dot(q, b) + radius) / pixel, OpenMesh::dot(q, d));
        }
        std::fill(depth.begin(), depth.end(), -std::numeric_limits<double>::max());
        std::fill(id.begin(), id.end(), -1);
        for (std::size_t t = 0; t < s.triangles.size(); ++t) {
            const Vec3 &p0 = projected[s.triangles[t][0]], &p1 = projected[s.triangles[t][1]],
                       &p2 = projected[s.triangles[t][2]];
            const double area = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
            const int x0 = std::max(0, static_cast<int>(std::floor(std::min({p0[0], p1[0], p2[0]}))));
            const int x1 =
                std::min(resolution - 1, static_cast<int>(std::floor(std::max({p0[0], p1[0], p2[0]}))));
            const int y0 = std::max(0, static_cast<int>(std::floor(std::min({p0[1], p1[1], p2[1]}))));
            const int y1 =
                std::min(resolution - 1, static_cast<int>(std::floor(std::max({p0[1], p1[1], p2[1]}))));
            // Triangles smaller than a pixel still claim the pixel of their centroid.
            const bool tiny = std::abs(area) < 1e-12 || (x1 - x0 < 1 && y1 - y0 < 1);
            for (int y = y0; y <= y1; ++y)
                for (int x = x0; x <= x1; ++x) {
                    const double px = x + 0.5, py = y + 0.5;
                    double w0, w1, w2;
                    if (tiny) {
                        w0 = w1 = w2 = 1.0 / 3.0;
                    } else {
                        w0 = ((p1[0] - px) * (p2[1] - py) - (p2[0] - px) * (p1[1] - py)) / area;
                        w1 = ((p2[0] - px) * (p0[1] - py) - (p0[0] - px) * (p2[1] - py)) / area;
                        w2 = 1.0 - w0 - w1;
                        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                    }
                    const double zz = w0 * p0[2] + w1 * p1[2] + w2 * p2[2];
                    const std::size_t pix = static_cast<std::size_t>(y) * resolution + x;
                    if (zz > depth[pix]) {
                        depth[pix] = zz;
                        id[pix] = static_cast<std::int64_t>(t);
                    }
                }
        }
        for (const auto t : id)
            if (t >= 0) visible[static_cast<std::size_t>(t)] = true;
    }
    return visible;
}

PointIndex::PointIndex(const std::vector<Vec3>& points, const std::vector<std::uint32_t>& subset, double cell)
    : points_(&points), cell_(std::max(cell, 1e-12)) {
    if (subset.empty()) return;
    Vec3 hi = points[subset[0]];
    lo_ = hi;
    for (const auto i : subset) {
        lo_.minimize(points[i]);
        hi.maximize(points[i]);
    }
    nx_ = static_cast<int>((hi[0] - lo_[0]) / cell_) + 1;
    ny_ = static_cast<int>((hi[1] - lo_[1]) / cell_) + 1;
    nz_ = static_cast<int>((hi[2] - lo_[2]) / cell_) + 1;
    // Keep the bucket count bounded for very fine cells.
    while (static_cast<double>(nx_) * ny_ * nz_ > 8e6) {
        cell_ *= 2.0;
        nx_ = static_cast<int>((hi[0] - lo_[0]) / cell_) + 1;
        ny_ = static_cast<int>((hi[1] - lo_[1]) / cell_) + 1;
        nz_ = static_cast<int>((hi[2] - lo_[2]) / cell_) + 1;
    }
    const std::size_t buckets = static_cast<std::size_t>(nx_) * ny_ * nz_;
    std::vector<std::uint32_t> count(buckets + 1, 0);
    const auto bucketOf = [&](const Vec3& p) {
        const int x = std::clamp(static_cast<int>((p[0] - lo_[0]) / cell_), 0, nx_ - 1);
        const int y = std::clamp(static_cast<int>((p[1] - lo_[1]) / cell_), 0, ny_ - 1);
        const int z = std::clamp(static_cast<int>((p[2] - lo_[2]) / cell_), 0, nz_ - 1);
        return static_cast<std::size_t>(key(x, y, z));
    };
    for (const auto i : subset) ++count[bucketOf(points[i])];
    start_.assign(buckets + 1, 0);
    for (std::size_t b = 0; b < buckets; ++b) start_[b + 1] = start_[b] + count[b];
    items_.resize(subset.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (const auto i : subset) items_[fill[bucketOf(points[i])]++] = i;
}

std::int64_t PointIndex::key(int x, int y, int z) const {
    return (static_cast<std::int64_t>(z) * ny_ + y) * nx_ + x;
}

std::int64_t PointIndex::nearest(const Vec3& p, double maxDistance) const {
    if (items_.empty()) return -1;
    const int reach = static_cast<int>(std::ceil(maxDistance / cell_));
    const int cx = static_cast<int>(std::floor((p[0] - lo_[0]) / cell_));
    const int cy = static_cast<int>(std::floor((p[1] - lo_[1]) / cell_));
    const int cz = static_cast<int>(std::floor((p[2] - lo_[2]) / cell_));
    std::int64_t best = -1;
    double bestD = maxDistance * maxDistance;
    // Shells of growing Chebyshev radius around p's bucket, until no closer point can remain.
    for (int r = 0; r <= reach; ++r) {
        for (int z = cz - r; z <= cz + r; ++z) {
            if (z < 0 || z >= nz_) continue;
            for (int y = cy - r; y <= cy + r; ++y) {
                if (y < 0 || y >= ny_) continue;
                const bool faceZY = std::abs(z - cz) == r || std::abs(y - cy) == r;
                for (int x = cx - r; x <= cx + r; x += faceZY ? 1 : 2 * std::max(r, 1)) {
                    if (x < 0 || x >= nx_) continue;
                    const auto b = static_cast<std::size_t>(key(x, y, z));
                    for (auto i = start_[b]; i < start_[b + 1]; ++i) {
                        const double d = ((*points_)[items_[i]] - p).sqrnorm();
                        if (d <= bestD) {
                            bestD = d;
                            best = items_[i];
                        }
                    }
                }
            }
        }
        if (best >= 0 && bestD <= (r * cell_) * (r * cell_)) break;
    }
    return best;
}

void PointIndex::within(const Vec3& p, double radius, std::vector<std::uint32_t>& out) const {
    out.clear();
    if (items_.empty()) return;
    const int reach = static_cast<int>(std::ceil(radius / cell_));
    const int cx = static_cast<int>(std::floor((p[0] - lo_[0]) / cell_));
    const int cy = static_cast<int>(std::floor((p[1] - lo_[1]) / cell_));
    const int cz = static_cast<int>(std::floor((p[2] - lo_[2]) / cell_));
    for (int z = std::max(0, cz - reach); z <= std::min(nz_ - 1, cz + reach); ++z)
        for (int y = std::max(0, cy - reach); y <= std::min(ny_ - 1, cy + reach); ++y)
            for (int x = std::max(0, cx - reach); x <= std::min(nx_ - 1, cx + reach); ++x) {
                const auto b = static_cast<std::size_t>(key(x, y, z));
                for (auto i = start_[b]; i < start_[b + 1]; ++i)
                    if (((*points_)[items_[i]] - p).sqrnorm() <= radius * radius) out.push_back(items_[i]);
            }
}

namespace {

// Principal axes of weighted points (Jacobi eigen-decomposition of the 3x3 covariance).
std::array<Vec3, 3> principalAxes(const std::vector<Vec3>& pts, const Vec3& mean) {
    double c[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    for (const auto& p : pts)
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) c[i][j] += (p[i] - mean[i]) * (p[j] - mean[j]);
    double v[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int sweep = 0; sweep < 50; ++sweep)
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (std::abs(c[p][q]) < 1e-18) continue;
                const double theta = 0.5 * std::atan2(2 * c[p][q], c[q][q] - c[p][p]);
                const double cs = std::cos(theta), sn = std::sin(theta);
                for (int k = 0; k < 3; ++k) {
                    const double a = c[k][p], b = c[k][q];
                    c[k][p] = cs * a - sn * b;
                    c[k][q] = sn * a + cs * b;
                }
                for (int k = 0; k < 3; ++k) {
                    const double a = c[p][k], b = c[q][k];
                    c[p][k] = cs * a - sn * b;
                    c[q][k] = sn * a + cs * b;
                }
                for (int k = 0; k < 3; ++k) {
                    const double a = v[k][p], b = v[k][q];
                    v[k][p] = cs * a - sn * b;
                    v[k][q] = sn * a + cs * b;
                }
            }
    return {Vec3(v[0][0], v[1][0], v[2][0]), Vec3(v[0][1], v[1][1], v[2][1]),
            Vec3(v[0][2], v[1][2], v[2][2])};
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

} // namespace

SymmetryPlane findSymmetryPlane(const WeldedSurface& s, const std::vector<std::uint32_t>& subset) {
    SymmetryPlane best;
    best.error = std::numeric_limits<double>::max();
    if (subset.size() < 8) return best;
    // At most about 3000 samples, spread over the subset.
    std::vector<std::uint32_t> sample;
    const std::size_t stride = std::max<std::size_t>(1, subset.size() / 3000);
    for (std::size_t k = 0; k < subset.size(); k += stride) sample.push_back(subset[k]);
    std::vector<Vec3> pts;
    Vec3 mean(0, 0, 0);
    for (const auto i : sample) {
        pts.push_back(s.points[i]);
        mean += s.points[i] / double(sample.size());
    }
    const double size = std::max(s.diagonal, 1e-12);
    const PointIndex index(s.points, subset, size / 64.0);
    const double reach = 0.25 * size;
    for (const Vec3& axis : principalAxes(pts, mean)) {
        SymmetryPlane plane;
        plane.normal = axis.normalized();
        plane.offset = OpenMesh::dot(plane.normal, mean);
        std::vector<double> mismatch;
        for (int iteration = 0; iteration < 12; ++iteration) {
            std::vector<std::pair<Vec3, Vec3>> pairs;
            mismatch.clear();
            for (const auto& p : pts) {
                const Vec3 m = plane.reflect(p);
                const auto q = index.nearest(m, reach);
                if (q < 0) continue;
                mismatch.push_back((s.points[static_cast<std::size_t>(q)] - m).norm());
                pairs.emplace_back(p, s.points[static_cast<std::size_t>(q)]);
            }
            if (pairs.size() < 8) break;
            const double cut = median(mismatch) * 2.0 + 1e-12;
            Vec3 normal(0, 0, 0), middle(0, 0, 0);
            double weight = 0.0;
            for (std::size_t k = 0; k < pairs.size(); ++k) {
                if (mismatch[k] > cut) continue;
                Vec3 d = pairs[k].first - pairs[k].second;
                if (OpenMesh::dot(d, plane.normal) < 0) d = -d;
                normal += d;
                middle += (pairs[k].first + pairs[k].second) * 0.5;
                weight += 1.0;
            }
            if (normal.norm() < 1e-12 || weight == 0.0) break;
            plane.normal = normal.normalized();
            plane.offset = OpenMesh::dot(plane.normal, middle / weight);
        }
        // Score: median mismatch of the mirrored samples.
        mismatch.clear();
        for (const auto& p : pts) {
            const auto q = index.nearest(plane.reflect(p), reach);
            mismatch.push_back(q < 0 ? reach
                                     : (s.points[static_cast<std::size_t>(q)] - plane.reflect(p)).norm());
        }
        plane.error = median(mismatch) / size;
        if (plane.error < best.error) best = plane;
    }
    return best;
}

} // namespace vl::face
