#pragma once
// Reading and writing meshes in formats other tools read: Wavefront OBJ, Stanford PLY (ASCII and
// binary little/big-endian) and VRML97 IndexedFaceSet. Every reader keeps the file's vertex order
// exactly (never splits, merges, drops or reorders vertices), triangulates polygons as a fan from
// their first corner (c0 c1 c2, c0 c2 c3, ...: the same way for every member of a viseme set), and
// rejects bad input with an InputError naming the file and the line ("file:12: ...") or, where a
// format has no lines, the element ("file: face 12: ...", elements counted from 0).
//
// Rejected everywhere: missing or empty file, no vertices, no faces, NaN/Inf coordinates, an index
// out of range (zero in OBJ, which counts from 1; negative in PLY; below -1 in VRML), a face with
// fewer than 3 corners and a degenerate face (the same vertex twice).
//
// Texture coordinates become one (u,v) per vertex. When a file indexes them separately from the
// vertices (OBJ `f v/vt`, VRML texCoordIndex; MediaPipe's and ICT's meshes do), each vertex takes
// the (u,v) of its first face corner in file order; at a UV seam (a vertex used with different
// (u,v)) that first one is kept, because vertices are never split. Vertices no corner gives a
// (u,v) get (0,0); so OBJ, which has no other way to give one, does not keep the (u,v) of vertices
// that no face uses. Without any texture coordinates `uvs` is empty.
//
// Writers print doubles in their shortest exact form (OBJ, VRML) or as float64 (PLY), so reading a
// written mesh gives back bit-identical positions, (u,v) and triangles. Writers given
// PositionPrecision::Float32 (the key meshes of a reduction and its exports) print each position
// coordinate as float32 instead; (u,v) and triangles stay exact.
#include "core/mesh/Mesh.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vl {

enum class MeshFormat { Obj, Ply, Vrml };

// How a writer prints vertex positions.
enum class PositionPrecision {
    // A double's shortest exact text (OBJ, VRML) or float64 (PLY): reads back bit-identical.
    Exact,
    // float32: OBJ and VRML print the shortest text that reads back as the same float32
    // (std::to_chars of static_cast<float>(x)), PLY stores double(static_cast<float>(x)); either way
    // static_cast<float> of the read-back value equals static_cast<float>(x). For key meshes (every
    // consumer - runtime package, glTF, Blender, XfaceEd - stores float32, and a frequency-weighted
    // mean's last double digits are noise): about half the text of Exact. A coordinate beyond
    // float32's range is refused ("mesh to write: ...").
    Float32,
};

// Texture coordinates as the file indexes them, per triangle corner: what a tool needs that samples
// a surface over its (u,v) and so must see the UV seams that one (u,v) per vertex hides (core/face).
// triangles[f][k] indexes texCoords for corner k of mesh triangle f (the same fan triangulation);
// a corner the file gives no texture coordinate is kNoTexCoord. Both are empty for a file without
// texture coordinates. For PLY (one (u,v) per vertex) texCoords are the vertices' (u,v).
struct CornerTexCoords {
    static constexpr std::uint32_t kNoTexCoord = 0xFFFFFFFFu;
    std::vector<Vec2> texCoords;
    std::vector<Triangle> triangles;
};

// Chooses the format from the extension (.obj, .ply, .wrl/.vrml, any letter case); throws
// InputError otherwise.
MeshFormat meshFormatFromPath(const std::filesystem::path& path);
bool isMeshFile(const std::filesystem::path& path);

// Reads any supported format; the result has at least one vertex and one triangle.
MeshData readMesh(const std::filesystem::path& path);
// The same, and the file's per-corner texture coordinates.
MeshData readMesh(const std::filesystem::path& path, CornerTexCoords& corners);

// A mesh read to stand for files of the same topology (a viseme set's neutral mesh).
struct ReferenceMesh {
    MeshData mesh;
    std::string objStructure; // OBJ: the file's lines with each `v` line's numbers left out
};
ReferenceMesh readReferenceMesh(const std::filesystem::path& path);
// The same result as readMesh(path). When `path` is an OBJ whose lines equal the reference's, in
// order, except the numbers of its `v` lines, its faces and texture coordinates are the reference's
// and only the `v` lines are parsed (a viseme exported beside its neutral mesh: a few times faster).
MeshData readMeshLike(const std::filesystem::path& path, const ReferenceMesh& reference);
// The same without copying the reference's faces and (u,v) (a viseme set keeps only the positions
// of its visemes): when `sameTopology`, `path` took that fast path, mesh.positions are its positions
// and its faces and (u,v) are the reference's (mesh.triangles and mesh.uvs are left empty);
// otherwise `mesh` is readMesh(path).
struct MeshLike {
    MeshData mesh;
    bool sameTopology = false;
};
MeshLike readPositionsLike(const std::filesystem::path& path, const ReferenceMesh& reference);
// Writes atomically (temp file + rename) in the format of the extension.
void writeMesh(const std::filesystem::path& path, const MeshData& mesh);
// The file contents writeMesh writes, for writers that stage files (core/common/OutputSet.h);
// formatObj, formatPly or formatVrml for Exact.
std::string formatMesh(const std::filesystem::path& path, const MeshData& mesh,
                       PositionPrecision precision = PositionPrecision::Exact);

// The positions of one mesh as text in `precision`, each coordinate formatted once for every file
// that writes them (a key mesh's OBJ and VRML). A coordinate whose value in `precision` has the same
// bits as the same vertex's same coordinate in `reference` (the neutral mesh: most of a face does
// not move in a viseme) copies the reference's text, which is the text formatting it gives.
class PositionText {
  public:
    PositionText() = default;
    // Throws InputError "mesh to write: ..." for positions a writer refuses (non-finite, beyond
    // float32's range for Float32).
    PositionText(std::span<const Vec3> positions, PositionPrecision precision,
                 const PositionText* reference = nullptr);
    // The same, reusing this object's buffers.
    void assign(std::span<const Vec3> positions, PositionPrecision precision,
                const PositionText* reference = nullptr);

    std::size_t vertexCount() const { return ends_.size() / 3; }
    PositionPrecision precision() const { return precision_; }
    // "x y z": the vertex's coordinates separated by single spaces.
    std::string_view vertex(std::size_t i) const;
    std::string_view coordinate(std::size_t i, int axis) const;
    // The positions as written: the doubles (Exact) or double(float(x)) (Float32).
    std::vector<Vec3> values() const;
    // Appends prefix + vertex(i) + separator for every vertex, `last` instead of the last separator.
    void appendLines(std::string& out, std::string_view prefix, std::string_view separator,
                     std::string_view last) const;

  private:
    std::size_t start(std::size_t c) const { return c == 0 ? 0 : ends_[c - 1] + (c % 3 == 0 ? 0 : 1); }

    PositionPrecision precision_ = PositionPrecision::Exact;
    std::string text_;                // every vertex's "x y z", one after another (then unused space)
    std::vector<std::size_t> ends_;   // end of coordinate c = 3 * vertex + axis in text_
    std::vector<std::uint64_t> bits_; // coordinate c's bits in `precision`
};

// Formats meshes of one topology (vertex count, triangles, (u,v)) - the key meshes of a reduction -
// in the format of `path`'s extension, the text that does not depend on the positions only once:
// format(p) == formatMesh(path, {p, topology.uvs, topology.triangles}, precision) for p of the
// topology's size.
class MeshTextFormatter {
  public:
    MeshTextFormatter(const std::filesystem::path& path, const MeshData& topology,
                      PositionPrecision precision);
    std::string format(std::span<const Vec3> positions) const;
    // The same text into `out` (replacing its contents): a buffer reused for many files keeps its
    // pages, where a fresh string of this size is mapped and faulted in anew each time.
    void format(std::span<const Vec3> positions, std::string& out) const;
    // The same from positions already formatted in this formatter's precision (throws
    // std::invalid_argument for another precision or vertex count): the OBJ and VRML of one key
    // mesh format its coordinates once.
    void format(const PositionText& positions, std::string& out) const;
    // The same file as parts to write one after another (OutputSet::add): head + middle + tail ==
    // format(positions). The text around the positions is the formatter's own, not copied into each
    // file's text; `buffer` holds the middle.
    struct Parts {
        std::string_view head, middle, tail;
    };
    Parts parts(const PositionText& positions, std::string& buffer) const;

  private:
    void requireFormatOf(const PositionText& positions) const;
    void appendPositions(std::string& out, const PositionText& positions) const;
    MeshFormat format_;
    PositionPrecision precision_;
    std::size_t vertexCount_;
    MeshData plyTopology_;    // PLY only: its (u,v) and triangles (the text formats keep only text)
    std::string head_, tail_; // OBJ and VRML: the file around the positions
};

// Format-level entry points on in-memory text; `source` names the file in error messages.
//
// OBJ: reads `v x y z` (extra w or colour values ignored), `vt u [v]`, and `f` corners written v,
// v/vt, v//vn or v/vt/vn with positive or negative (relative) indices ('#' starts a comment
// anywhere). Other statements (vn, vp, o, g, s, usemtl, mtllib, l, ...) are ignored, except
// unknown ones starting with v or f (say `V` or `vx`), which are rejected: skipping a line that may
// be a vertex would renumber every vertex after it. Line continuations ('\') are not supported.
MeshData parseObj(std::string_view text, std::string_view source);
// The same, and the file's per-corner texture coordinates.
MeshData parseObj(std::string_view text, std::string_view source, CornerTexCoords& corners);
// The structure readMeshLike compares: every line of `text`, a `v` line as just "v".
std::string objStructure(std::string_view text);
// The positions of `text` when objStructure(text) == structure, else nothing; errors in `v` lines
// are reported as parseObj reports them.
std::optional<std::vector<Vec3>> parseObjPositionsMatching(std::string_view text, std::string_view source,
                                                           std::string_view structure);
// `v` lines, `vt` lines when the mesh has (u,v), and `f a b c` or `f a/a b/b c/c`.
std::string formatObj(const MeshData& mesh);

// PLY: the `vertex` element's x, y, z (any numeric type) and (u,v) from u/v, s/t, texture_u/
// texture_v or texture_s/texture_t; the `face` element's vertex_indices (or vertex_index) list of
// any integer types. Other properties and elements are skipped.
MeshData parsePly(std::string_view bytes, std::string_view source);
std::string formatPly(const MeshData& mesh); // binary little-endian, float64: bit-exact round trip

// VRML97: every IndexedFaceSet (inside any Transform/Shape/Group nesting) with its
// `coord Coordinate { point [...] }`, `coordIndex`, and optional `texCoord TextureCoordinate` and
// `texCoordIndex` (without texCoordIndex, vertex i takes texture coordinate i, as the VRML spec
// has coordIndex index both). Several IndexedFaceSets are concatenated into one mesh in file order (the first
// set's vertices come first), which matches XfaceEd's submesh numbering "file.wrl_0", "_1", ...
// Transforms are ignored: positions are taken as written. DEF/USE of Coordinate and
// TextureCoordinate nodes is resolved; a USE of a whole IndexedFaceSet does not add its geometry
// again. PROTO declarations are skipped. VRML 1.0 and gzip-compressed files are rejected.
MeshData parseVrml(std::string_view text, std::string_view source);
MeshData parseVrml(std::string_view text, std::string_view source, CornerTexCoords& corners);
// `#VRML V2.0 utf8` with one Shape { IndexedFaceSet } holding all vertices and triangles, and a
// TextureCoordinate with one (u,v) per vertex (no texCoordIndex) when the mesh has them.
std::string formatVrml(const MeshData& mesh);

} // namespace vl
