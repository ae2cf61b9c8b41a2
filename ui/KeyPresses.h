#pragma once
// Key presses as GLFW reports them, queued until the next frame takes them. ImGui 1.86 keeps only
// whether a key is down when a frame starts, so a press and its release between two frames (a
// quick tap, or any tap on a loaded machine) never shows as pressed: the shortcuts read this queue.
#include <cstdint>
#include <vector>

struct GLFWwindow;

namespace vl::ui {

struct KeyPress {
    int key = 0;  // GLFW_KEY_*
    int mods = 0; // GLFW_MOD_*
    bool repeat = false;
    bool ctrl() const;
    bool shift() const;
};

// Installs the queue's key callback; call before ImGui_ImplGlfw_InitForOpenGL, which chains its own
// callback to it.
void installKeyPresses(GLFWwindow* window);
// The presses since the last call, oldest first.
std::vector<KeyPress> takeKeyPresses();
// How many keys other than modifiers and locks were pressed so far (for the GUI tests' probe).
std::uint64_t keyPressCount();

} // namespace vl::ui
