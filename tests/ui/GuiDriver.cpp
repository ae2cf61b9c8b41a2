#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <thread>

extern char** environ;

namespace vl::test {
namespace {

using Clock = std::chrono::steady_clock;

bool onPath(const char* tool) {
    return std::system((std::string("command -v ") + tool + " > /dev/null 2>&1").c_str()) == 0;
}

// Starts `argv` (environment `environment`), stdout and stderr appended to `output`, optionally
// writing to the inherited descriptor `keepOpen`. The child gets SIGKILL when the test process dies
// (an interrupted test never leaves an editor spinning on a core).
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& environment,
            const std::filesystem::path& output, int keepOpen = -1) {
    std::vector<char*> args, envp;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    for (const std::string& e : environment) envp.push_back(const_cast<char*>(e.c_str()));
    envp.push_back(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("cannot start " + argv[0]);
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec.
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent) _exit(127);
        const int fd = open(output.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            if (fd != keepOpen) close(fd);
        }
        execve(argv[0].c_str(), args.data(), envp.data());
        _exit(127);
    }
    return pid;
}

std::vector<std::string> environmentWithDisplay(const std::string& display) {
    std::vector<std::string> environment;
    for (char** e = environ; *e; ++e)
        if (std::string_view(*e).substr(0, 8) != "DISPLAY=") environment.emplace_back(*e);
    if (!display.empty()) environment.push_back("DISPLAY=" + display);
    return environment;
}

std::string which(const char* tool) {
    std::FILE* p = popen((std::string("command -v ") + tool).c_str(), "r");
    char buffer[512] = {};
    const bool ok = p && std::fgets(buffer, sizeof buffer, p);
    if (p) pclose(p);
    std::string path = ok ? buffer : "";
    while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) path.pop_back();
    return path;
}

std::string readAll(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

void stop(pid_t pid) {
    if (pid <= 0) return;
    kill(pid, SIGTERM);
    for (int i = 0; i < 100; ++i) {
        if (waitpid(pid, nullptr, WNOHANG) == pid) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid, SIGKILL);
    waitpid(pid, nullptr, 0);
}

} // namespace

std::string missingGuiTools() {
    std::string missing;
    if (!onPath("Xvfb")) missing += " Xvfb (apt-get install xvfb)";
    if (!onPath("xdotool")) missing += " xdotool (apt-get install xdotool)";
    return missing;
}

GuiDriver::GuiDriver(const std::vector<std::string>& arguments, int width, int height) {
    std::random_device random;
    folder_ = std::filesystem::temp_directory_path() /
              ("visemelab-gui-" + std::to_string(getpid()) + "-" + std::to_string(random()));
    std::filesystem::create_directories(folder_);
    probeFile_ = folder_ / "probe.json";
    logFile_ = folder_ / "editor.log";

    // A private X server on a free display: -displayfd writes the number it chose.
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe");
    {
        const std::string screen = std::to_string(width) + "x" + std::to_string(height) + "x24";
        xvfb_ =
            spawn({which("Xvfb"), "-displayfd", std::to_string(fds[1]), "-screen", "0", screen, "-nolisten",
                   "tcp", "-r"}, // no autorepeat: a key held while the editor is slow must not type twice
                  environmentWithDisplay({}), folder_ / "xvfb.log", fds[1]);
    }
    close(fds[1]);
    std::string number;
    char c = 0;
    while (read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    close(fds[0]);
    if (number.empty()) throw std::runtime_error("Xvfb did not start: " + readAll(folder_ / "xvfb.log"));
    display_ = ":" + number;

    std::vector<std::string> argv = {VISEMELAB_EDITOR,      "--probe",
                                     probeFile_.string(),   "--size",
                                     std::to_string(width), std::to_string(height)};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    editor_ = spawn(argv, environmentWithDisplay(display_), logFile_);

    // The window id: xdotool sends events relative to it.
    waitFrames(2);
    std::FILE* p = popen(("DISPLAY=" + display_ + " timeout 20 xdotool search --sync --pid " +
                          std::to_string(editor_) + " 2>/dev/null")
                             .c_str(),
                         "r");
    char buffer[64] = {};
    if (p && std::fgets(buffer, sizeof buffer, p)) window_ = buffer;
    if (p) pclose(p);
    while (!window_.empty() && (window_.back() == '\n')) window_.pop_back();
    if (window_.empty()) throw std::runtime_error("xdotool cannot find the editor window");
    xdotool("windowfocus --sync " + window_); // no window manager gives it the keyboard
    moveTo(width - 2, height - 2);            // start from a neutral place (over no control)
    waitFrames(3);
}

GuiDriver::~GuiDriver() {
    if (editorStatus_ < 0) stop(editor_);
    stop(xvfb_);
    std::error_code ignored;
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(folder_, ignored);
}

bool GuiDriver::alive() {
    if (editorStatus_ >= 0) return false;
    int status = 0;
    if (waitpid(editor_, &status, WNOHANG) == editor_) {
        editorStatus_ = status;
        return false;
    }
    return true;
}

std::string GuiDriver::exitStatus() const {
    if (editorStatus_ < 0) return "running";
    if (WIFSIGNALED(editorStatus_)) return "killed by signal " + std::to_string(WTERMSIG(editorStatus_));
    return "exit code " + std::to_string(WEXITSTATUS(editorStatus_));
}

std::string GuiDriver::windowTitle() const {
    std::FILE* p =
        popen(("DISPLAY=" + display_ + " xdotool getwindowname " + window_ + " 2>/dev/null").c_str(), "r");
    std::string title;
    char buffer[512];
    while (p && std::fgets(buffer, sizeof buffer, p)) title += buffer;
    if (p) pclose(p);
    while (!title.empty() && title.back() == '\n') title.pop_back();
    return title;
}

std::string GuiDriver::log() const {
    return readAll(logFile_);
}

const nlohmann::json& GuiDriver::waitFrames(int frames) {
    const long start = report_.is_null() ? 0 : report_.value("frame", 0L);
    const auto deadline = Clock::now() + std::chrono::seconds(60);
    while (Clock::now() < deadline) {
        if (!alive()) throw std::runtime_error("the editor exited (" + exitStatus() + "):\n" + log());
        std::error_code error;
        if (std::filesystem::exists(probeFile_, error)) {
            try {
                nlohmann::json report = nlohmann::json::parse(readAll(probeFile_));
                if (!report["duplicate_ids"].empty())
                    ADD_FAILURE() << "controls sharing one ImGui ID (their state is shared): "
                                  << report["duplicate_ids"].dump();
                if (report.value("frame", 0L) >= start + frames) {
                    report_ = std::move(report);
                    return report_;
                }
            } catch (const nlohmann::json::exception&) {
                // replaced between exists() and the read: try again
            }
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(15));
    }
    throw std::runtime_error("the editor drew no frame for 60 s");
}

const nlohmann::json& GuiDriver::waitIdle(double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    waitFrames(1);
    while (document().value("busy", false) && Clock::now() < deadline) waitFrames(1);
    return waitFrames(1);
}

std::optional<nlohmann::json> GuiDriver::find(const std::string& text, const std::string& kind,
                                              int nth) const {
    for (const nlohmann::json& control : report_["controls"]) {
        if (!kind.empty() && control["kind"] != kind) continue;
        if (control["text"] != text && control["label"] != text) continue;
        if (nth-- == 0) return control;
    }
    return std::nullopt;
}

nlohmann::json GuiDriver::control(const std::string& text, const std::string& kind, int nth) const {
    const auto found = find(text, kind, nth);
    if (!found)
        throw std::runtime_error("no " + (kind.empty() ? "control" : kind) + " '" + text + "' on screen");
    return *found;
}

void GuiDriver::xdotool(const std::string& arguments) {
    if (std::getenv("VISEMELAB_GUI_TRACE")) std::fprintf(stderr, "xdotool %s\n", arguments.c_str());
    const std::string command = "DISPLAY=" + display_ + " xdotool " + arguments + " > /dev/null 2>&1";
    if (std::system(command.c_str()) != 0) throw std::runtime_error("xdotool failed: " + command);
}

template <class Predicate> void GuiDriver::waitUntil(const Predicate& seen, const std::string& what) {
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    waitFrames(1);
    while (!seen(report_["input"])) {
        if (Clock::now() > deadline) throw std::runtime_error("the editor never saw " + what);
        waitFrames(1);
    }
}

void GuiDriver::moveTo(double x, double y) {
    const int ix = static_cast<int>(x), iy = static_cast<int>(y);
    xdotool("mousemove --window " + window_ + " " + std::to_string(ix) + " " + std::to_string(iy));
    waitUntil(
        [&](const nlohmann::json& input) {
            return std::abs(input["x"].get<double>() - ix) < 1.0 &&
                   std::abs(input["y"].get<double>() - iy) < 1.0;
        },
        "the mouse at " + std::to_string(ix) + "," + std::to_string(iy));
}

void GuiDriver::press(int button, bool down) {
    xdotool(std::string(down ? "mousedown " : "mouseup ") + std::to_string(button));
    const int index = button == 1 ? 0 : button == 3 ? 1 : 2;
    waitUntil([&](const nlohmann::json& input) { return input["buttons"][index].get<bool>() == down; },
              std::string("button ") + std::to_string(button) + (down ? " down" : " up"));
}

nlohmann::json GuiDriver::reveal(const std::string& text, const std::string& kind) {
    for (int attempt = 0; attempt < 40; ++attempt) {
        const nlohmann::json c = control(text, kind);
        if (c.value("visible", true)) return c;
        // Scroll inside the control's column, towards it: up when it lies above the window's top.
        const double x = c["x"].get<double>() + 5.0;
        const bool above = c["y"].get<double>() < 150.0;
        scroll(x, 400.0, above ? -2 : 2);
    }
    throw std::runtime_error("the " + kind + " '" + text + "' never came into view");
}

nlohmann::json GuiDriver::revealAtEnd(const std::string& text, const std::string& kind) {
    for (int attempt = 0; attempt < 20; ++attempt) {
        const auto found = find(text, kind);
        if (found && found->value("visible", true)) return *found;
        scroll(200, 500, 5);
        waitFrames(2);
    }
    return control(text, kind);
}

void GuiDriver::click(const nlohmann::json& control, double fx, double fy) {
    // A real user cannot click a row scrolled out of its list (the click lands on something else).
    if (!control.value("visible", true))
        throw std::runtime_error("'" + control["label"].get<std::string>() +
                                 "' is outside its window's visible area");
    clickAt(control["x"].get<double>() + fx * control["width"].get<double>(),
            control["y"].get<double>() + fy * control["height"].get<double>());
}

// A human click: move, let the editor see the hover, press, hold a little, release.
void GuiDriver::clickAt(double x, double y, int button) {
    moveTo(x, y);
    press(button, true);
    press(button, false);
    waitFrames(1);
}

void GuiDriver::hover(double x, double y) {
    moveTo(x, y);
    waitFrames(2);
}

void GuiDriver::drag(double x0, double y0, double x1, double y1, int steps) {
    moveTo(x0, y0);
    waitFrames(1);
    press(1, true);
    for (int i = 1; i <= steps; ++i) {
        const double t = static_cast<double>(i) / steps;
        moveTo(x0 + t * (x1 - x0), y0 + t * (y1 - y0));
    }
    press(1, false);
    waitFrames(2);
}

// Wheel notches are not held state: each is given a few frames to arrive.
void GuiDriver::scroll(double x, double y, int notches) {
    moveTo(x, y);
    const int button = notches > 0 ? 5 : 4;
    for (int i = 0; i < std::abs(notches); ++i) {
        xdotool("click " + std::to_string(button));
        waitFrames(2);
    }
    waitFrames(2);
}

// Held until the editor saw it, as a person holds a key: ImGui 1.86 samples key state once per
// frame, so a press and release inside one frame (xdotool key) would be missed.
void GuiDriver::key(const std::string& keys) {
    // Every key of a chord ("ctrl+s") must be seen down in one frame: waiting for the first one only
    // could release "s" before the editor sampled it.
    const int chord = 1 + static_cast<int>(std::count(keys.begin(), keys.end(), '+'));
    xdotool("keydown " + keys);
    waitUntil([&](const nlohmann::json& input) { return input["keys_down"].get<int>() >= chord; },
              "key " + keys);
    // Release in reverse order (the key before its modifiers): releasing ctrl first lets an
    // autorepeat of a held "a" reach the editor as a plain "a" on a loaded machine.
    std::vector<std::string> parts;
    for (std::size_t start = 0; start <= keys.size();) {
        const std::size_t plus = std::min(keys.find('+', start), keys.size());
        parts.push_back(keys.substr(start, plus - start));
        start = plus + 1;
    }
    std::string release;
    for (auto part = parts.rbegin(); part != parts.rend(); ++part) release += " " + *part;
    xdotool("keyup" + release);
    waitUntil([](const nlohmann::json& input) { return input["keys_down"].get<int>() == 0; },
              "key " + keys + " released");
    waitFrames(2);
}

void GuiDriver::type(const std::string& text) {
    xdotool("type --delay 30 '" + text + "'");
    waitFrames(3);
}

void GuiDriver::tap(const std::string& keys, bool wait) {
    waitFrames(1);
    const auto start = document().value("key_presses", std::uint64_t{0});
    xdotool("key --delay 0 " + keys);
    if (!wait) return;
    // Each chord ("w", "ctrl+KP_1") is one key besides its modifiers.
    const auto chords = static_cast<std::uint64_t>(1 + std::count(keys.begin(), keys.end(), ' '));
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    while (document().value("key_presses", std::uint64_t{0}) < start + chords) {
        if (Clock::now() > deadline) throw std::runtime_error("the editor never saw the keys " + keys);
        waitFrames(1);
    }
    waitFrames(2);
}

std::filesystem::path GuiDriver::screenshot(const std::string& name) {
    const std::filesystem::path picture = folder_ / (name + ".png");
    const std::filesystem::path request = probeFile_.string() + ".screenshot";
    std::ofstream(request) << picture.string();
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    while (std::filesystem::exists(request) && Clock::now() < deadline) waitFrames(1);
    waitFrames(1); // the frame that took it has ended: the file is whole
    return picture;
}

bool GuiDriver::waitForExit(double seconds) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(seconds);
    while (alive() && Clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return !alive();
}

void GuiDriver::chooseFile(const std::filesystem::path& file, const std::string& button) {
    if (!document().value("file_dialog_open", false)) throw std::runtime_error("no file dialog is open");
    click(control("##name", "text"));
    key("ctrl+a");
    type(file.string());
    click(control(button, "button"));
    waitIdle();
}

void writeGridVisemeFolder(const std::filesystem::path& dir, const std::vector<std::string>& names, int side,
                           const std::function<double(int, int, int)>& height) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    for (std::size_t v = 0; v <= names.size(); ++v) {
        std::ofstream obj(dir / ((v == 0 ? std::string("neutral") : names[v - 1]) + ".obj"));
        for (int i = 0; i < side; ++i)
            for (int j = 0; j < side; ++j)
                obj << "v " << i << ' ' << j << ' ' << (v == 0 ? 0.0 : height(static_cast<int>(v), i, j))
                    << '\n';
        for (int i = 0; i + 1 < side; ++i)
            for (int j = 0; j + 1 < side; ++j) {
                const int a = i * side + j + 1, b = a + 1, c = a + side, d = c + 1;
                obj << "f " << a << ' ' << b << ' ' << d << "\nf " << a << ' ' << d << ' ' << c << '\n';
            }
    }
}

} // namespace vl::test
