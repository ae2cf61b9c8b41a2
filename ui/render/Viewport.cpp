#include "ui/render/Viewport.h"
#include "ui/probe/GuiProbe.h"
#include "ui/render/SceneSignature.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace vl::ui {
namespace {
constexpr GLsizei kSamples = 4;
constexpr float kOrbitRadiansPerPixel = 0.008f;
} // namespace

Viewport::~Viewport() {
    release();
}

void Viewport::release() {
    if (msaaFbo_) glDeleteFramebuffers(1, &msaaFbo_);
    if (resolveFbo_) glDeleteFramebuffers(1, &resolveFbo_);
    if (msaaColor_) glDeleteRenderbuffers(1, &msaaColor_);
    if (msaaDepth_) glDeleteRenderbuffers(1, &msaaDepth_);
    if (resolveTexture_) glDeleteTextures(1, &resolveTexture_);
    msaaFbo_ = resolveFbo_ = msaaColor_ = msaaDepth_ = resolveTexture_ = 0;
    width_ = height_ = 0;
    shownSignature_.reset();
}

void Viewport::resize(int width, int height) {
    if (width == width_ && height == height_ && msaaFbo_) return;
    release();
    width_ = width;
    height_ = height;
    glGenRenderbuffers(1, &msaaColor_);
    glBindRenderbuffer(GL_RENDERBUFFER, msaaColor_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, kSamples, GL_RGBA8, width, height);
    glGenRenderbuffers(1, &msaaDepth_);
    glBindRenderbuffer(GL_RENDERBUFFER, msaaDepth_);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, kSamples, GL_DEPTH_COMPONENT24, width, height);
    glGenFramebuffers(1, &msaaFbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, msaaFbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaaColor_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaaDepth_);

    glGenTextures(1, &resolveTexture_);
    glBindTexture(GL_TEXTURE_2D, resolveTexture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glGenFramebuffers(1, &resolveFbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, resolveTexture_, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

void Viewport::render(const SceneFn& scene, const glm::mat4& view, const glm::mat4& projection) {
    GLint previousViewport[4];
    glGetIntegerv(GL_VIEWPORT, previousViewport);
    glBindFramebuffer(GL_FRAMEBUFFER, msaaFbo_);
    glViewport(0, 0, width_, height_);
    glClearColor(background.r, background.g, background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_MULTISAMPLE);
    scene(view, projection);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msaaFbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolveFbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(previousViewport[0], previousViewport[1], previousViewport[2], previousViewport[3]);
}

ViewportEvents Viewport::show(const char* id, ImVec2 size, const SceneFn& scene, bool leftDragOrbits) {
    ViewportEvents events;
    const int width = std::max(16, static_cast<int>(size.x));
    const int height = std::max(16, static_cast<int>(size.y));
    resize(width, height);
    events.aspect = static_cast<float>(width) / static_cast<float>(height);

    // The scene is drawn again only when what it shows changed (a moved camera, an edit, a new
    // weight ...): its draws recorded first as a signature, compared with the one on screen.
    const glm::mat4 view = camera.view(), projection = camera.projection(events.aspect);
    drawnProjection_ = projection;
    SceneSignature signature;
    {
        const SceneSignature::Recording recording(signature);
        scene(view, projection);
    }
    signature.addValue(background);
    if (!shownSignature_ || *shownSignature_ != signature.value()) {
        render(scene, view, projection);
        shownSignature_ = signature.value();
        ++renders_;
    }

    ImGui::PushID(id);
    const ImTextureID texture = reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(resolveTexture_));
    ImGui::Image(texture, ImVec2(static_cast<float>(width), static_cast<float>(height)), ImVec2(0, 1),
                 ImVec2(1, 0));
    probe::recordArea(id, "view");
    events.imageMin = ImGui::GetItemRectMin();
    events.imageMax = ImGui::GetItemRectMax();
    const ImVec2 mousePos = ImGui::GetIO().MousePos;
    const bool overExcluded = mousePos.x >= excludedMin_.x && mousePos.x < excludedMax_.x &&
                              mousePos.y >= excludedMin_.y && mousePos.y < excludedMax_.y;
    excludedMin_ = excludedMax_ = ImVec2(0, 0);
    events.hovered = ImGui::IsItemHovered() && !overExcluded;
    ImGui::PopID();

    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 mouse = io.MousePos;
    events.ndc = {2.0f * (mouse.x - events.imageMin.x) / static_cast<float>(width) - 1.0f,
                  1.0f - 2.0f * (mouse.y - events.imageMin.y) / static_cast<float>(height)};

    // Drags belong to the view they started in, even when the mouse leaves it.
    if (events.hovered && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
        leftDragActive_ = true;
        events.leftPressed = true;
    }
    if (events.hovered &&
        (ImGui::IsMouseClicked(ImGuiMouseButton_Right) || ImGui::IsMouseClicked(ImGuiMouseButton_Middle)))
        otherDragActive_ = true;
    if (leftDragActive_ && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        leftDragActive_ = false;
        events.leftReleased = true;
    }
    if (otherDragActive_ && !ImGui::IsMouseDown(ImGuiMouseButton_Right) &&
        !ImGui::IsMouseDown(ImGuiMouseButton_Middle))
        otherDragActive_ = false;
    events.leftDown = leftDragActive_;

    const auto heightF = static_cast<float>(height);
    if (leftDragActive_ && leftDragOrbits)
        camera.orbit(-io.MouseDelta.x * kOrbitRadiansPerPixel, io.MouseDelta.y * kOrbitRadiansPerPixel);
    if (otherDragActive_) camera.pan(io.MouseDelta.x / heightF, io.MouseDelta.y / heightF);
    if (events.hovered && io.MouseWheel != 0.0f) camera.zoom(std::pow(0.9f, io.MouseWheel));
    if (events.hovered && !io.WantTextInput) {
        const float step = 2.0f * io.DeltaTime;
        if (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) camera.orbit(step, 0.0f);
        if (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) camera.orbit(-step, 0.0f);
        if (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_UpArrow))) camera.orbit(0.0f, step);
        if (ImGui::IsKeyDown(ImGui::GetKeyIndex(ImGuiKey_DownArrow))) camera.orbit(0.0f, -step);
    }
    return events;
}

} // namespace vl::ui
