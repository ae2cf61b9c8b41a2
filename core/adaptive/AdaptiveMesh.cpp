#include "core/adaptive/AdaptiveMesh.h"

#include "core/adaptive/Criteria.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <deque>
#include <stdexcept>

namespace vl {
namespace {

using FaceHandle = OpenMesh::FaceHandle;
using VertexHandle = OpenMesh::VertexHandle;

// Faces queued for a refinement test, each at most once at a time.
class FaceQueue {
  public:
    void push(FaceHandle f) {
        const auto i = static_cast<std::size_t>(f.idx());
        if (i >= queued_.size()) queued_.resize(std::max(i + 1, 2 * queued_.size()), 0);
        if (queued_[i]) return;
        queued_[i] = 1;
        faces_.push_back(f);
    }
    bool empty() const { return faces_.empty(); }
    FaceHandle pop() {
        const FaceHandle f = faces_.front();
        faces_.pop_front();
        queued_[static_cast<std::size_t>(f.idx())] = 0;
        return f;
    }

  private:
    std::deque<FaceHandle> faces_;
    std::vector<char> queued_;
};

} // namespace

AdaptiveMesh::AdaptiveMesh(const Surface& surface, RbmtMethod method)
    : surface_(&surface), base_(makeRbmtBase(surface.baseDomain(), method)) {
    mesh_.request_vertex_texcoords2D();
    mesh_.add_property(vertexLevel_);
    mesh_.add_property(faceLevel_);
    mesh_.add_property(refinementMark_);
    buildFromBase();
    for (std::size_t t = 0; t < base_.triangles.size(); ++t) {
        const auto& tri = base_.triangles[t];
        const auto k = base_.refinementEdge[t];
        baseBlockEdges_.insert(edgeKey(tri[k], tri[(k + 1) % 3]));
    }
}

void AdaptiveMesh::buildFromBase() {
    mesh_.clean(); // no elements; the properties stay
    deletedFaces_ = deletedVertices_ = 0;
    for (const auto& uv : base_.uvs) {
        const auto v = mesh_.add_vertex(surface_->sample(uv));
        mesh_.set_texcoord2D(v, uv);
        mesh_.property(vertexLevel_, v) = 0;
    }
    for (std::size_t t = 0; t < base_.triangles.size(); ++t) {
        const auto& tri = base_.triangles[t];
        const auto f = mesh_.add_face(mesh_.vertex_handle(tri[0]), mesh_.vertex_handle(tri[1]),
                                      mesh_.vertex_handle(tri[2]));
        if (!f.is_valid()) throw std::logic_error("adaptive mesh: validated base triangle rejected");
        mesh_.property(faceLevel_, f) = 0;
        const auto k = base_.refinementEdge[t];
        for (const auto h : mesh_.fh_range(f))
            mesh_.property(refinementMark_, h) =
                mesh_.from_vertex_handle(h).idx() == static_cast<int>(tri[k]) &&
                mesh_.to_vertex_handle(h).idx() == static_cast<int>(tri[(k + 1) % 3]);
    }
}

std::uint64_t AdaptiveMesh::edgeKey(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

OpenMesh::HalfedgeHandle AdaptiveMesh::refinementHalfedge(FaceHandle f) const {
    for (const auto h : mesh_.fh_range(f))
        if (isRefinementHalfedge(h)) return h;
    throw std::logic_error("adaptive mesh: face " + std::to_string(f.idx()) + " has no refinement edge");
}

int AdaptiveMesh::maxLevel() const {
    int result = 0;
    for (const auto f : mesh_.faces()) result = std::max(result, level(f));
    return result;
}

bool AdaptiveMesh::isBlockEdge(EdgeHandle e) const {
    if (mesh_.status(e).deleted()) return false;
    const auto h0 = mesh_.halfedge_handle(e, 0), h1 = mesh_.halfedge_handle(e, 1);
    const auto f0 = mesh_.face_handle(h0), f1 = mesh_.face_handle(h1);
    if (!f0.is_valid()) return isRefinementHalfedge(h1);
    if (!f1.is_valid()) return isRefinementHalfedge(h0);
    return isRefinementHalfedge(h0) && isRefinementHalfedge(h1) && level(f0) == level(f1);
}

void AdaptiveMesh::markFaces(const std::vector<FaceHandle>& faces, int faceLevel, VertexHandle a,
                             VertexHandle b) {
    for (const auto f : faces) {
        mesh_.property(faceLevel_, f) = faceLevel;
        for (const auto h : mesh_.fh_range(f)) {
            const auto from = mesh_.from_vertex_handle(h), to = mesh_.to_vertex_handle(h);
            mesh_.property(refinementMark_, h) = (from == a && to == b) || (from == b && to == a);
        }
    }
}

OpenMesh::VertexHandle AdaptiveMesh::splitBlock(EdgeHandle e) {
    if (!isBlockEdge(e)) throw std::logic_error("adaptive mesh: split of an edge that is not a block edge");
    const auto h0 = mesh_.halfedge_handle(e, 0);
    const auto a = mesh_.from_vertex_handle(h0), b = mesh_.to_vertex_handle(h0);
    const auto f = mesh_.face_handle(h0).is_valid() ? mesh_.face_handle(h0)
                                                    : mesh_.face_handle(mesh_.halfedge_handle(e, 1));
    const int childLevel = level(f) + 1;
    const Vec2 uv = 0.5 * (mesh_.texcoord2D(a) + mesh_.texcoord2D(b));
    const auto v = mesh_.add_vertex(surface_->sample(uv));
    mesh_.set_texcoord2D(v, uv);
    mesh_.property(vertexLevel_, v) = childLevel;
    mesh_.split(e, v);
    // Each child's refinement edge is the one opposite the new vertex (an external edge of the block).
    for (const auto child : mesh_.vf_range(v)) {
        mesh_.property(faceLevel_, child) = childLevel;
        for (const auto h : mesh_.fh_range(child))
            mesh_.property(refinementMark_, h) =
                mesh_.from_vertex_handle(h) != v && mesh_.to_vertex_handle(h) != v;
    }
    return v;
}

OpenMesh::VertexHandle AdaptiveMesh::refineFace(FaceHandle f) {
    return refineFace(f, nullptr);
}

OpenMesh::VertexHandle AdaptiveMesh::refineFace(FaceHandle f, std::vector<VertexHandle>* created) {
    const auto h = refinementHalfedge(f);
    const auto e = mesh_.edge_handle(h);
    if (!isBlockEdge(e)) {
        // Across the refinement edge lies a face one level coarser for which this edge is a leg:
        // splitting it makes one of its children our block partner.
        const auto g = mesh_.face_handle(mesh_.opposite_halfedge_handle(h));
        if (!g.is_valid() || level(g) != level(f) - 1 ||
            isRefinementHalfedge(mesh_.opposite_halfedge_handle(h)))
            throw std::logic_error("adaptive mesh: RBMT structure violated at face " +
                                   std::to_string(f.idx()));
        refineFace(g, created);
    }
    const auto v = splitBlock(e);
    if (created) created->push_back(v);
    return v;
}

bool AdaptiveMesh::weldEndpoints(VertexHandle v, VertexHandle& a, VertexHandle& b) const {
    if (mesh_.status(v).deleted() || level(v) < 1) return false;
    const bool border = mesh_.is_boundary(v);
    std::vector<VertexHandle> ring;
    for (const auto n : mesh_.vv_range(v)) ring.push_back(n);
    if (ring.size() != (border ? 3u : 4u)) return false;
    for (const auto f : mesh_.vf_range(v)) {
        if (level(f) != level(v)) return false;
        for (const auto h : mesh_.fh_range(f)) {
            const bool opposite = mesh_.from_vertex_handle(h) != v && mesh_.to_vertex_handle(h) != v;
            if (isRefinementHalfedge(h) != opposite) return false;
        }
    }
    const Vec2 uv = mesh_.texcoord2D(v);
    auto isSplitEdge = [&](VertexHandle x, VertexHandle y) {
        if (0.5 * (mesh_.texcoord2D(x) + mesh_.texcoord2D(y)) != uv) return false;
        if (level(v) >= 2) return level(x) < level(v) - 1 && level(y) < level(v) - 1;
        return baseBlockEdges_.count(
                   edgeKey(static_cast<std::uint32_t>(x.idx()), static_cast<std::uint32_t>(y.idx()))) > 0;
    };
    if (border) {
        // The split edge is the border edge: its halves are v's two boundary edges.
        int found = 0;
        for (const auto h : mesh_.voh_range(v)) {
            if (!mesh_.is_boundary(mesh_.edge_handle(h))) continue;
            (found++ == 0 ? a : b) = mesh_.to_vertex_handle(h);
        }
        return found == 2 && isSplitEdge(a, b);
    }
    // Inside: the split edge is one of the two diagonals of the ring; the other joins the apexes,
    // which have the block's level (they are the newest vertices of its faces).
    const bool first = isSplitEdge(ring[0], ring[2]), second = isSplitEdge(ring[1], ring[3]);
    if (first == second) return false;
    a = first ? ring[0] : ring[1];
    b = first ? ring[2] : ring[3];
    return true;
}

bool AdaptiveMesh::canWeld(VertexHandle v) const {
    VertexHandle a, b;
    return weldEndpoints(v, a, b);
}

std::vector<OpenMesh::FaceHandle> AdaptiveMesh::weld(VertexHandle v) {
    VertexHandle a, b;
    if (!weldEndpoints(v, a, b))
        throw std::logic_error("adaptive mesh: weld of a vertex that cannot be welded");
    const int blockLevel = level(v) - 1;
    const auto toA = mesh_.find_halfedge(v, a);
    if (!mesh_.is_collapse_ok(toA)) throw std::logic_error("adaptive mesh: weld rejected by OpenMesh");
    const std::size_t facesBefore = mesh_.valence(v) == 3 ? 2 : 4;
    mesh_.collapse(toA);
    ++deletedVertices_;
    deletedFaces_ += facesBefore / 2;
    const auto h = mesh_.find_halfedge(a, b);
    std::vector<FaceHandle> restored;
    for (const auto side : {h, mesh_.opposite_halfedge_handle(h)})
        if (const auto f = mesh_.face_handle(side); f.is_valid()) restored.push_back(f);
    markFaces(restored, blockLevel, a, b);
    return restored;
}

std::vector<OpenMesh::FaceHandle> AdaptiveMesh::affectedFaces(const std::vector<FaceHandle>& changed,
                                                              const Criterion& criterion) const {
    if (!criterion.readsNeighbourhood()) return changed;
    std::vector<FaceHandle> out;
    for (const auto f : changed)
        for (const auto v : mesh_.fv_range(f))
            for (const auto g : mesh_.vf_range(v)) out.push_back(g);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

AdaptStats AdaptiveMesh::refine(const Criterion& criterion) {
    return refineFrom(criterion, std::vector<FaceHandle>(mesh_.faces_begin(), mesh_.faces_end()));
}

AdaptStats AdaptiveMesh::refineFrom(const Criterion& criterion, const std::vector<FaceHandle>& start) {
    // In rounds: every queued face is tested in parallel against the mesh as the round found it (the
    // tests are ~75 % of the time), then the faces that failed are split in queue order. A split changes
    // the faces around its new vertices; those are queued again (affectedFaces, as one face at a time
    // would) and their test of this round is stale, so they are not split on it. Every split is thus
    // decided on the faces exactly as they are when it happens, and the round ends with every face
    // either tested on its current neighbourhood or queued: the invariant of the one-at-a-time loop.
    constexpr std::size_t kGrain = 32;
    AdaptStats stats;
    const int maxDepth = criterion.maxDepth();
    FaceQueue queue;
    for (const auto f : start) queue.push(f);
    std::vector<FaceHandle> round;
    std::vector<char> fails;
    std::vector<std::uint32_t> changedInRound; // per face: the round that last changed it
    std::uint32_t roundNumber = 0;
    std::vector<VertexHandle> created;
    std::vector<FaceHandle> changed;
    while (!queue.empty()) {
        round.clear();
        while (!queue.empty()) {
            const auto f = queue.pop();
            if (!mesh_.status(f).deleted() && level(f) < maxDepth) round.push_back(f);
        }
        stats.tests += round.size();
        fails.assign(round.size(), 0);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, round.size(), kGrain), [&](const auto& range) {
            for (std::size_t i = range.begin(); i != range.end(); ++i)
                fails[i] = criterion.needsRefinement(*this, round[i]) ? 1 : 0;
        });
        ++roundNumber;
        for (std::size_t i = 0; i < round.size(); ++i) {
            const auto f = round[i];
            const auto index = static_cast<std::size_t>(f.idx());
            if (!fails[i] || mesh_.status(f).deleted() ||
                (index < changedInRound.size() && changedInRound[index] == roundNumber))
                continue;
            created.clear();
            refineFace(f, &created);
            stats.splits += created.size();
            changed.clear();
            for (const auto v : created)
                for (const auto child : mesh_.vf_range(v)) changed.push_back(child);
            for (const auto g : affectedFaces(changed, criterion)) {
                queue.push(g);
                const auto k = static_cast<std::size_t>(g.idx());
                if (k >= changedInRound.size())
                    changedInRound.resize(std::max(k + 1, 2 * changedInRound.size()), 0);
                changedInRound[k] = roundNumber;
            }
        }
    }
    return stats;
}

AdaptStats AdaptiveMesh::simplify(const Criterion& criterion) {
    return simplifyWithin(criterion, UvBox::everywhere());
}

bool AdaptiveMesh::faceMeets(FaceHandle f, const UvBox& region) const {
    UvBox box;
    for (const auto v : mesh_.fv_range(f)) box.include({uv(v), uv(v)});
    return region.meets(box.lo, box.hi);
}

bool AdaptiveMesh::ringMeets(VertexHandle v, const UvBox& region) const {
    UvBox box{uv(v), uv(v)};
    for (const auto w : mesh_.vv_range(v)) box.include({uv(w), uv(w)});
    return region.meets(box.lo, box.hi);
}

AdaptStats AdaptiveMesh::simplifyWithin(const Criterion& criterion, const UvBox& region) {
    const bool everywhere = region.isEverywhere();
    AdaptStats stats;
    std::vector<VertexHandle> candidates;
    while (true) {
        candidates.clear();
        for (const auto v : mesh_.vertices())
            if (level(v) >= 1 && (everywhere || ringMeets(v, region))) candidates.push_back(v);
        // Finest first: welding children makes their parents' centres weldable in the same round.
        std::stable_sort(candidates.begin(), candidates.end(),
                         [&](VertexHandle x, VertexHandle y) { return level(x) > level(y); });
        std::size_t welded = 0;
        for (const auto v : candidates) {
            VertexHandle a, b;
            if (!weldEndpoints(v, a, b)) continue;
            const auto restored = weld(v);
            const auto affected = affectedFaces(restored, criterion);
            stats.tests += affected.size();
            if (criterion.allowsSimplification(*this, affected)) {
                ++welded;
                continue;
            }
            // Still needed: split again (the same (u,v) midpoint, so exactly the same vertex).
            splitBlock(mesh_.edge_handle(mesh_.find_halfedge(a, b)));
        }
        stats.welds += welded;
        if (welded == 0) break;
    }
    collectGarbage();
    return stats;
}

AdaptStats AdaptiveMesh::adapt(const Criterion& criterion, const UvBox& changed) {
    // Rebuild when the change reaches more than this share of the vertices: a full re-adaptation
    // (resample, weld tests everywhere, refine tests everywhere) costs more than refining the base
    // mesh again (bench_adaptive BM_ReadaptContourJaw against BM_RebuildContourJaw).
    constexpr double kRebuildShare = 0.5;
    if (changed.empty()) return {};
    if (!changed.isEverywhere()) {
        std::size_t inside = 0, live = 0;
        for (const auto v : mesh_.vertices()) {
            ++live;
            if (changed.contains(uv(v))) ++inside;
        }
        if (static_cast<double>(inside) > kRebuildShare * static_cast<double>(live)) {
            buildFromBase();
            AdaptStats stats = refine(criterion);
            stats.rebuilt = true;
            return stats;
        }
    }
    resampleWithin(changed);
    AdaptStats stats = simplifyWithin(criterion, changed);
    std::vector<FaceHandle> start;
    for (const auto f : mesh_.faces())
        if (faceMeets(f, changed)) start.push_back(f);
    const AdaptStats refined = refineFrom(criterion, affectedFaces(start, criterion));
    stats.splits += refined.splits;
    stats.tests += refined.tests;
    return stats;
}

void AdaptiveMesh::resample() {
    resampleWithin(UvBox::everywhere());
}

void AdaptiveMesh::resampleWithin(const UvBox& region) {
    const auto n = static_cast<int>(mesh_.n_vertices());
    tbb::parallel_for(0, n, [&](int i) {
        const auto v = mesh_.vertex_handle(i);
        if (!mesh_.status(v).deleted() && region.contains(uv(v))) mesh_.set_point(v, surface_->sample(uv(v)));
    });
}

void AdaptiveMesh::collectGarbage() {
    if (deletedFaces_ == 0 && deletedVertices_ == 0) return;
    mesh_.garbage_collection();
    deletedFaces_ = deletedVertices_ = 0;
}

MeshData AdaptiveMesh::toMeshData() const {
    MeshData out;
    std::vector<std::uint32_t> index(mesh_.n_vertices(), UINT32_MAX);
    out.positions.reserve(vertexCount());
    out.uvs.reserve(vertexCount());
    for (const auto v : mesh_.vertices()) {
        index[static_cast<std::size_t>(v.idx())] = static_cast<std::uint32_t>(out.positions.size());
        out.positions.push_back(mesh_.point(v));
        out.uvs.push_back(mesh_.texcoord2D(v));
    }
    out.triangles.reserve(faceCount());
    for (const auto f : mesh_.faces()) {
        Triangle t{};
        int k = 0;
        for (const auto v : mesh_.fv_range(f)) t[k++] = index[static_cast<std::size_t>(v.idx())];
        out.triangles.push_back(t);
    }
    return out;
}

} // namespace vl
