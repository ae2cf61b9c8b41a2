#pragma once
// What a 3D view shows, as one number: a view re-renders its scene only when this changes (an idle
// editor, or one busy in its side panel, then costs ImGui's quads instead of a multisampled scene;
// with a software renderer that is most of a frame). Every draw of a view goes through
// GpuMesh::draw, which, while a signature is being recorded, adds its inputs (mesh and its upload
// revision, weights, matrices, style, shader) to it instead of drawing.
#include <cstddef>
#include <cstdint>

namespace vl::ui {

class SceneSignature {
  public:
    void add(const void* bytes, std::size_t size);
    template <class T> void addValue(const T& value) { add(&value, sizeof value); }
    std::uint64_t value() const { return hash_; }

    // The signature being recorded on this thread, or null when draws are real.
    static SceneSignature* recording();

    // While alive, draws on this thread are recorded into `signature` instead of drawn.
    class Recording {
      public:
        explicit Recording(SceneSignature& signature);
        ~Recording();
        Recording(const Recording&) = delete;
        Recording& operator=(const Recording&) = delete;

      private:
        SceneSignature* previous_;
    };

  private:
    std::uint64_t hash_ = 14695981039346656037ull; // FNV-1a offset basis
};

// A number never handed out before in this process: the revision of an uploaded GPU buffer set, so
// a mesh destroyed and another created at the same address never share a signature.
std::uint64_t nextUploadRevision();

} // namespace vl::ui
