#pragma once
// Orbit camera: rotates around a target point, pans in the view plane, zooms along the view axis;
// perspective or orthographic, and the standard views (front, back, sides, top, bottom).
//
// Convention: +Y up, the face looks along +Z at the viewer (the bundled faces and glTF avatars
// alike), so the front view looks down -Z. The sides follow Blender: "right" is seen from +X (the
// viewer's right of the front view), the top has the back of the head up on the screen.
#include <glm/glm.hpp>

#include <optional>
#include <string_view>

namespace vl::ui {

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction; // unit length
};

enum class StandardView { Front, Back, Right, Left, Top, Bottom };
const char* standardViewName(StandardView view);                         // "Front", ...
std::optional<StandardView> standardViewFromName(std::string_view name); // case-insensitive

class OrbitCamera {
  public:
    glm::mat4 view() const;
    // Perspective, or orthographic with the extent the perspective shows at the target's depth.
    glm::mat4 projection(float aspect) const;
    glm::vec3 eye() const;

    // Angles in radians; pitch stays within the poles (+-pi/2: straight down or up).
    void orbit(float deltaYaw, float deltaPitch);
    // Looks at the target from that side, keeping the target and the distance.
    void setView(StandardView view);
    // Moves the target by a fraction of the visible height (dx, dy in viewport heights).
    void pan(float dx, float dy);
    // factor > 1 moves away, < 1 moves closer.
    void zoom(float factor);
    // Looks at the box centre from the current direction, at a distance that fits the whole box.
    void frame(const glm::vec3& lo, const glm::vec3& hi);
    // The ray through a point given in normalised device coordinates ([-1,1]^2, y up).
    Ray rayThrough(float ndcX, float ndcY, float aspect) const;
    // World length that covers one viewport height at the target's depth (either projection).
    float visibleHeightAtTarget() const;

    float yaw = 0.0f;
    float pitch = 0.0f;
    float distance = 3.0f;
    float fovY = 0.6f; // radians
    bool orthographic = false;
    glm::vec3 target{0.0f};
};

} // namespace vl::ui
