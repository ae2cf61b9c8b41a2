#pragma once
// A 3D view inside an ImGui window: renders a scene into its own multisampled framebuffer (again
// only when what it shows changed: SceneSignature), shows it as an image and turns mouse/keyboard input over
// it into camera moves (left drag orbits, right or middle drag pans, wheel zooms, arrow keys orbit;
// +/- zoom is a shortcut of the window, EditorUi).
#include "ui/render/Camera.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <imgui.h>

#include <cstdint>
#include <functional>
#include <optional>

namespace vl::ui {

struct ViewportEvents {
    bool hovered = false;
    bool leftDown = false;     // left button held, started inside this view
    bool leftPressed = false;  // went down this frame inside this view
    bool leftReleased = false; // released this frame after a press inside this view
    glm::vec2 ndc{0.0f};       // mouse position in normalised device coordinates
    float aspect = 1.0f;
    ImVec2 imageMin{0, 0}, imageMax{0, 0}; // screen rectangle of the image
};

class Viewport {
  public:
    Viewport() = default;
    ~Viewport();
    Viewport(const Viewport&) = delete;
    Viewport& operator=(const Viewport&) = delete;

    using SceneFn = std::function<void(const glm::mat4& view, const glm::mat4& projection)>;
    // Renders `scene` at `size` (pixels) and places the image at the ImGui cursor. When
    // `leftDragOrbits` is false the left button is left to the caller (e.g. painting).
    ViewportEvents show(const char* id, ImVec2 size, const SceneFn& scene, bool leftDragOrbits = true);

    // Clicks inside this screen rectangle (an overlay such as the (u,v) inset) start no camera drag;
    // it applies to the next show() only.
    void excludeFromDrags(ImVec2 min, ImVec2 max) {
        excludedMin_ = min;
        excludedMax_ = max;
    }

    // How many times the scene was rendered (not shown again): for the GUI tests' idle checks.
    std::uint64_t renders() const { return renders_; }
    // The projection of the last show() (its aspect is the view's).
    const glm::mat4& drawnProjection() const { return drawnProjection_; }

    OrbitCamera camera;
    glm::vec3 background{0.16f, 0.17f, 0.20f};

  private:
    void resize(int width, int height);
    void release();
    void render(const SceneFn& scene, const glm::mat4& view, const glm::mat4& projection);

    int width_ = 0, height_ = 0;
    GLuint msaaFbo_ = 0, msaaColor_ = 0, msaaDepth_ = 0;
    GLuint resolveFbo_ = 0, resolveTexture_ = 0;
    std::optional<std::uint64_t> shownSignature_; // of the scene in resolveTexture_
    std::uint64_t renders_ = 0;
    glm::mat4 drawnProjection_{1.0f};
    bool leftDragActive_ = false, otherDragActive_ = false;
    ImVec2 excludedMin_{0, 0}, excludedMax_{0, 0};
};

} // namespace vl::ui
