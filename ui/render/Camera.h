#pragma once
// Orbit camera: rotates around a target point, pans in the view plane, zooms along the view axis.
#include <glm/glm.hpp>

namespace vl::ui {

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction; // unit length
};

class OrbitCamera {
  public:
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;
    glm::vec3 eye() const;

    // Angles in radians; pitch is clamped short of the poles so "up" stays defined.
    void orbit(float deltaYaw, float deltaPitch);
    // Moves the target by a fraction of the visible height (dx, dy in viewport heights).
    void pan(float dx, float dy);
    // factor > 1 moves away, < 1 moves closer.
    void zoom(float factor);
    // Looks at the box centre from the current direction, at a distance that fits the whole box.
    void frame(const glm::vec3& lo, const glm::vec3& hi);
    // The ray through a point given in normalised device coordinates ([-1,1]^2, y up).
    Ray rayThrough(float ndcX, float ndcY, float aspect) const;
    // World length that covers one viewport height at the target's depth.
    float visibleHeightAtTarget() const;

    float yaw = 0.0f;
    float pitch = 0.0f;
    float distance = 3.0f;
    float fovY = 0.6f; // radians
    glm::vec3 target{0.0f};
};

} // namespace vl::ui
