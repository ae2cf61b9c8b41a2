#pragma once
// Drives the real editor window with real input events, as a user would: a private Xvfb server,
// the editor process started with --probe (it reports its controls' rectangles and a document
// summary after every frame, see ui/probe/GuiProbe.h), and xdotool for mouse and keyboard.
// Nothing is injected into ImGui: events go through X11, GLFW and the ImGui backend.
#include <nlohmann/json.hpp>

#include <sys/types.h>

#include <cstdint>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

namespace vl::test {

// Empty when Xvfb and xdotool are both installed, else what is missing (for GTEST_SKIP).
std::string missingGuiTools();

// A folder the editor opens with --visemes: `dir`/neutral.obj, a flat side x side grid, and one OBJ
// per name with the grid's heights height(viseme 1.., i, j), called in file order.
void writeGridVisemeFolder(const std::filesystem::path& dir, const std::vector<std::string>& names, int side,
                           const std::function<double(int, int, int)>& height);

class GuiDriver {
  public:
    // Starts Xvfb and the editor with `arguments` (plus --probe and --size); waits for its first frames.
    explicit GuiDriver(const std::vector<std::string>& arguments, int width = 1600, int height = 1000);
    ~GuiDriver();
    GuiDriver(const GuiDriver&) = delete;
    GuiDriver& operator=(const GuiDriver&) = delete;

    // False once the editor process has exited (crashed or quit); exitStatus() says how.
    bool alive();
    std::string exitStatus() const;
    // The editor's stderr so far (for failure messages).
    std::string log() const;

    // Waits until the editor has drawn `frames` more frames and returns its latest report.
    const nlohmann::json& waitFrames(int frames = 3);
    // Waits until no background work runs (reduction, refinement, save ...), at most `seconds`.
    const nlohmann::json& waitIdle(double seconds = 60.0);
    const nlohmann::json& report() const { return report_; }
    const nlohmann::json& document() const { return report_["document"]; }

    // The control whose shown text (or full label) is `text`, optionally of a kind ("button",
    // "radio", "slider", "tab", "menu", "menuitem", ...) and the n-th such match; null when absent.
    std::optional<nlohmann::json> find(const std::string& text, const std::string& kind = {},
                                       int nth = 0) const;
    // The same, failing the test when the control is not there.
    nlohmann::json control(const std::string& text, const std::string& kind = {}, int nth = 0) const;

    // The control, after scrolling the window under it until it is in view (a user scrolls to
    // reach a control below the fold too); fails the test when it never comes into view.
    nlohmann::json reveal(const std::string& text, const std::string& kind = {});
    // The same for a control not drawn yet (ImGui skips what lies far below the fold): scrolls the
    // side panel down until it is there and in view (the Say section ends the Reduction panel).
    nlohmann::json revealAtEnd(const std::string& text, const std::string& kind);

    // Left click at a fraction of the control's rectangle (0.5, 0.5 = its centre).
    void click(const nlohmann::json& control, double fx = 0.5, double fy = 0.5);
    void clickAt(double x, double y, int button = 1);
    // Moves the pointer there (no button) and waits until the editor drew a frame with it there.
    void hover(double x, double y);
    // Press at one point, move in steps, release at another (a slider drag or a brush stroke).
    void drag(double x0, double y0, double x1, double y1, int steps = 8);
    // Mouse wheel over a point: positive = down.
    void scroll(double x, double y, int notches);
    // xdotool key names: "Escape", "Return", "ctrl+z", "Tab".
    void key(const std::string& keys);
    void type(const std::string& text);
    // Quick taps: each press and release sent at once (xdotool key, no delay), as a fast typist's
    // keys may reach the editor within one frame. Waits until the editor took them (and two more
    // frames), unless `wait` is false (a key that quits the editor).
    void tap(const std::string& keys, bool wait = true);
    // A picture of the window as the editor drew its next frame (PNG in the test's folder).
    std::filesystem::path screenshot(const std::string& name);
    // Waits up to `seconds` for the editor to exit by itself; true when it did.
    bool waitForExit(double seconds);
    // In the open file dialog: types `file` into its name field, presses `button` ("Open" or
    // "Save") and waits until the editor is idle. Fails the test when no dialog is open.
    void chooseFile(const std::filesystem::path& file, const std::string& button = "Open");
    // The window's title as the X server has it (what a window manager shows).
    std::string windowTitle() const;

  private:
    void xdotool(const std::string& arguments);
    // Waits (up to 30 s) until the editor's report satisfies `seen`: the event has arrived.
    template <class Predicate> void waitUntil(const Predicate& seen, const std::string& what);
    void press(int button, bool down);
    void moveTo(double x, double y);

    pid_t xvfb_ = -1, editor_ = -1;
    int editorStatus_ = -1;
    std::string display_;
    std::filesystem::path folder_, probeFile_, logFile_;
    std::string window_;
    nlohmann::json report_;
};

// Whether the status bar holds an error, and its newest message (the probe's "messages").
inline bool hasError(const GuiDriver& gui) {
    for (const auto& message : gui.document()["messages"])
        if (message["error"].get<bool>()) return true;
    return false;
}
inline std::string lastMessage(const GuiDriver& gui) {
    const auto& messages = gui.document()["messages"];
    return messages.empty() ? std::string() : messages.back()["text"].get<std::string>();
}

// A file's bytes (empty when it cannot be read): outputs compared with inputs.
inline std::string fileBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The editor's document revision from the probe summary: it changes with every edit, undo and redo.
inline std::uint64_t documentRevision(const GuiDriver& gui) {
    return gui.document()["document_revision"].get<std::uint64_t>();
}

} // namespace vl::test

// For the click tests: skip with a message without Xvfb/xdotool; fail with the editor's log when it
// is gone.
#define REQUIRE_GUI_TOOLS()                                                                                  \
    if (const std::string missing = ::vl::test::missingGuiTools(); !missing.empty())                         \
    GTEST_SKIP() << "GUI click tests need" << missing

#define EXPECT_ALIVE(gui)                                                                                    \
    ASSERT_TRUE((gui).alive()) << "editor " << (gui).exitStatus() << ":\n" << (gui).log()
