#include "ui/KeyPresses.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <utility>

namespace vl::ui {
namespace {

std::uint64_t pressed = 0;

std::vector<KeyPress>& queue() {
    static std::vector<KeyPress> presses; // GLFW calls back on the main thread, in glfwPollEvents
    return presses;
}

void onKey(GLFWwindow*, int key, int, int action, int mods) {
    if (action == GLFW_PRESS || action == GLFW_REPEAT) queue().push_back({key, mods, action == GLFW_REPEAT});
    const bool modifier = (key >= GLFW_KEY_LEFT_SHIFT && key <= GLFW_KEY_RIGHT_SUPER) ||
                          (key >= GLFW_KEY_CAPS_LOCK && key <= GLFW_KEY_NUM_LOCK);
    if (action == GLFW_PRESS && !modifier) ++pressed;
}

} // namespace

bool KeyPress::ctrl() const {
    return (mods & GLFW_MOD_CONTROL) != 0;
}

bool KeyPress::shift() const {
    return (mods & GLFW_MOD_SHIFT) != 0;
}

void installKeyPresses(GLFWwindow* window) {
    glfwSetKeyCallback(window, onKey);
}

std::uint64_t keyPressCount() {
    return pressed;
}

std::vector<KeyPress> takeKeyPresses() {
    return std::exchange(queue(), {});
}

} // namespace vl::ui
