#include "core/adaptive/Invariants.h"

#include <algorithm>
#include <cmath>

namespace vl {
namespace {

double signedArea(const Vec2& a, const Vec2& b, const Vec2& c) {
    const Vec2 e1 = b - a, e2 = c - a;
    return 0.5 * (e1[0] * e2[1] - e1[1] * e2[0]);
}

bool insideTriangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
    const double area = signedArea(a, b, c);
    const double tolerance = -1e-12 * std::abs(area);
    return signedArea(p, b, c) >= tolerance && signedArea(a, p, c) >= tolerance &&
           signedArea(a, b, p) >= tolerance;
}

bool insideDomain(const RbmtBase& base, const Vec2& p) {
    for (const auto& t : base.triangles)
        if (insideTriangle(p, base.uvs[t[0]], base.uvs[t[1]], base.uvs[t[2]])) return true;
    return false;
}

std::string name(const char* kind, int idx) {
    return std::string(kind) + " " + std::to_string(idx);
}

} // namespace

std::vector<std::string> checkAdaptiveMesh(const AdaptiveMesh& am) {
    std::vector<std::string> errors;
    auto fail = [&](std::string message) {
        if (errors.size() < 50) errors.push_back(std::move(message));
    };
    const TriMesh& m = am.mesh();
    const RbmtBase& base = am.base();

    double area = 0.0, baseArea = 0.0;
    for (const auto& t : base.triangles)
        baseArea += signedArea(base.uvs[t[0]], base.uvs[t[1]], base.uvs[t[2]]);

    std::size_t faces = 0;
    for (const auto f : m.faces()) {
        ++faces;
        const std::string where = name("face", f.idx());
        std::vector<OpenMesh::VertexHandle> vs;
        int marks = 0;
        for (const auto h : m.fh_range(f)) {
            vs.push_back(m.from_vertex_handle(h));
            marks += am.isRefinementHalfedge(h);
            const auto o = m.opposite_halfedge_handle(h);
            if (m.from_vertex_handle(o) != m.to_vertex_handle(h) ||
                m.to_vertex_handle(o) != m.from_vertex_handle(h))
                fail(where + ": opposite halfedges are not reversed");
            if (m.status(m.from_vertex_handle(h)).deleted()) fail(where + ": uses a deleted vertex");
        }
        if (vs.size() != 3) {
            fail(where + ": not a triangle");
            continue;
        }
        const double a = signedArea(am.uv(vs[0]), am.uv(vs[1]), am.uv(vs[2]));
        if (!(a > 0)) fail(where + ": not counter-clockwise in (u,v)");
        area += a;
        if (marks != 1) {
            fail(where + ": has " + std::to_string(marks) + " refinement edges");
            continue;
        }
        const int l = am.level(f);
        const auto r = am.refinementHalfedge(f);
        const auto newest = m.to_vertex_handle(m.next_halfedge_handle(r));
        if (l >= 1 && am.level(newest) != l) fail(where + ": newest vertex is not at the face level");
        for (const auto v : vs)
            if (am.level(v) > l) fail(where + ": has a vertex finer than the face");
        const auto o = m.opposite_halfedge_handle(r);
        if (const auto g = m.face_handle(o); g.is_valid()) {
            const bool partner = am.level(g) == l && am.isRefinementHalfedge(o);
            const bool coarser = am.level(g) == l - 1 && !am.isRefinementHalfedge(o);
            if (!partner && !coarser)
                fail(where + ": refinement edge is neither a block edge nor a coarser face's leg");
        }
        for (const auto g : m.ff_range(f))
            if (std::abs(am.level(g) - l) > 1)
                fail(where + ": level differs by more than one from " + name("face", g.idx()));
    }
    if (faces != am.faceCount()) fail("live face count differs from faceCount()");
    if (std::abs(area - baseArea) > 1e-9 * std::abs(baseArea))
        fail("faces do not tile the base domain in (u,v)");

    for (const auto e : m.edges()) {
        const bool f0 = m.face_handle(m.halfedge_handle(e, 0)).is_valid();
        const bool f1 = m.face_handle(m.halfedge_handle(e, 1)).is_valid();
        if (!f0 && !f1) fail(name("edge", e.idx()) + ": has no face");
    }

    std::size_t vertices = 0, baseVertices = 0;
    for (const auto v : m.vertices()) {
        ++vertices;
        const std::string where = name("vertex", v.idx());
        if (!m.is_manifold(v)) fail(where + ": not manifold");
        if (m.is_isolated(v)) fail(where + ": isolated");
        const Vec2 uv = am.uv(v);
        if (!(am.surface().sample(uv) == am.position(v)))
            fail(where + ": position differs from the surface sample");
        if (am.level(v) == 0) {
            ++baseVertices;
            const auto i = static_cast<std::size_t>(v.idx());
            if (i >= base.uvs.size() || !(base.uvs[i] == uv)) fail(where + ": level 0 but not a base vertex");
        } else if (!insideDomain(base, uv)) {
            fail(where + ": (u,v) outside the base domain");
        }
    }
    if (vertices != am.vertexCount()) fail("live vertex count differs from vertexCount()");
    if (baseVertices != base.uvs.size()) fail("base vertices missing");
    return errors;
}

} // namespace vl
