#include "ui/EditorApp.h"
#include "ui/WindowTitle.h"

#include "core/common/Error.h"
#include "core/reduce/Weights.h"
#include "ui/EditorUi.h"
#include "ui/KeyPresses.h"
#include "ui/UiScale.h"
#include "ui/probe/GuiProbe.h"
#include "ui/session/EditorSession.h"

#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <stb_image_write.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace vl::ui {
namespace {

std::string lastGlfwError;

void onGlfwError(int, const char* description) {
    lastGlfwError = description ? description : "unknown error";
}

// The interface's scale: the window's content scale (HiDPI), or VISEMELAB_UI_SCALE when set (a
// forced scale, for testing under Xvfb where it is 1).
float contentScale(GLFWwindow* window) {
    if (const char* forced = std::getenv("VISEMELAB_UI_SCALE")) {
        char* end = nullptr;
        const float value = std::strtof(forced, &end);
        if (end != forced && value >= 0.5f && value <= 4.0f) return value;
    }
    float x = 1.0f, y = 1.0f;
    glfwGetWindowContentScale(window, &x, &y);
    return std::clamp(std::max(x, y), 0.5f, 4.0f);
}

// Fonts and style at `scale`; again whenever the window moves to a screen of another scale (the
// font atlas is rebuilt: a scaled bitmap font would be blurred).
void setupFontsAndStyle(float scale) {
    uiScaleSetting() = scale;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // fixed layout: nothing to remember
    io.Fonts->Clear();
    // DejaVu Sans covers IPA (phoneme symbols: ŋ is Latin Extended-A, θ Greek) and the arrows and
    // dashes of messages; ImGui's default font is Latin-1 only.
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0100, 0x017F, 0x0180, 0x024F, 0x0250,
                                     0x02FF, 0x0300, 0x036F, 0x0370, 0x03FF, 0x1D00, 0x1DBF,
                                     0x2000, 0x206F, 0x2190, 0x21FF, 0x2500, 0x25FF, 0};
    const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    if (std::FILE* f = std::fopen(font, "rb")) {
        std::fclose(f);
        io.Fonts->AddFontFromFileTTF(font, kBaseFontSize * scale, nullptr, ranges);
    } else {
        ImFontConfig config;
        config.SizePixels = 13.0f * scale;
        io.Fonts->AddFontDefault(&config);
    }
    ImGuiStyle& style = ImGui::GetStyle();
    style = ImGuiStyle();
    ImGui::StyleColorsDark();
    style.WindowRounding = 0.0f;
    style.FrameRounding = 4.0f;
    style.GrabRounding = 4.0f;
    style.TabRounding = 4.0f;
    style.FramePadding = ImVec2(6, 4);
    style.ItemSpacing = ImVec2(8, 6);
    style.Colors[ImGuiCol_WindowBg] = ImVec4(0.11f, 0.12f, 0.14f, 1.0f);
    style.Colors[ImGuiCol_MenuBarBg] = ImVec4(0.09f, 0.10f, 0.12f, 1.0f);
    style.ScaleAllSizes(scale);
}

bool contentScaleChanged = false;

void onContentScale(GLFWwindow*, float, float) {
    contentScaleChanged = true;
}

// Applies the start options in order, each on its own: a bad one is passed to `failed` (which may
// throw to stop) and the others still apply, so `--project broken.vlproj --panel Weights` opens the
// Weights panel with the project's error shown.
void applyStartOptions(const EditorOptions& options, EditorSession& session, EditorUi& ui,
                       const std::function<void(const InputError&)>& failed) {
    const auto step = [&](bool given, const std::function<void()>& apply) {
        if (!given) return;
        try {
            apply();
        } catch (const InputError& e) {
            failed(e);
        }
    };
    const auto needFace = [&] {
        if (!session.document().face.cascade) session.face().load();
    };
    step(!options.project.empty(), [&] { session.files().openProject(options.project); });
    step(options.sample, [&] { session.files().loadSample(); });
    step(!options.visemeFolder.empty(), [&] { session.files().loadVisemeFolder(options.visemeFolder); });
    step(!options.avatar.empty(),
         [&] { session.files().importAvatar(options.avatar, options.avatarTargets); });
    step(!options.panel.empty(), [&] {
        const auto panel = panelFromName(options.panel);
        if (!panel) throwInputError("--panel", "unknown panel '" + options.panel + "'");
        ui.selectPanel(*panel);
        if (*panel == Panel::Deformation) needFace();
    });
    step(!options.viseme.empty(), [&] {
        const int index = session.visemes() ? session.visemes()->find(options.viseme) : -1;
        if (index < 0) throwInputError("--viseme", "no viseme named '" + options.viseme + "'");
        session.selectViseme(index);
    });
    bool refine = false; // the refinement starts after the face's other options, if its criterion is valid
    step(!options.refine.empty(), [&] {
        needFace();
        CriterionSettings settings = session.document().refinement;
        settings.kind = parseEnum<CriterionKind>(options.refine, "--refine");
        session.face().setRefinementSettings(settings);
        refine = true;
    });
    step(!options.individual.empty(), [&] {
        needFace();
        session.face().setIndividual(parseEnum<face::Individual>(options.individual, "--individual"));
    });
    step(!options.ownFace.empty(), [&] {
        needFace();
        session.face().openOwnFace(options.ownFace);
    });
    step(!options.preset.empty(), [&] {
        needFace();
        session.face().applyVisemePreset(options.preset);
    });
    step(refine, [&] { session.face().startRefinement(RefineAction::Refine); });
    step(!options.field.empty(), [&] {
        needFace();
        if (!ui.selectField(options.field))
            throwInputError("--field", "no analytic field named '" + options.field + "'");
    });
    ui.setWireframe(options.wireframe);
    step(!options.view.empty() || options.orthographic, [&] {
        const auto view = options.view.empty() ? StandardView::Front : standardViewFromName(options.view);
        if (!view)
            throwInputError("--view",
                            "expected front, back, right, left, top or bottom, got '" + options.view + "'");
        ui.setStartView(*view, options.orthographic);
    });
    step(!options.weights.empty(), [&] {
        const auto mode = fromString<WeightMode>(options.weights);
        if (!mode)
            throwInputError("--weights", "expected uniform, area or painted, got '" + options.weights + "'");
        session.weights().setMode(*mode);
    });
    step(!options.brush.empty(), [&] {
        const std::string modes[] = {"add", "subtract", "smooth"};
        const auto it = std::find(std::begin(modes), std::end(modes), options.brush);
        if (it == std::end(modes))
            throwInputError("--brush", "expected add, subtract or smooth, got '" + options.brush + "'");
        ui.enableBrush(static_cast<int>(it - std::begin(modes)));
    });
    step(!options.sculpt.empty(), [&] {
        for (const SculptTool tool :
             {SculptTool::Grab, SculptTool::Smooth, SculptTool::Inflate, SculptTool::Deflate})
            if (sculptToolName(tool) == options.sculpt) return ui.enableSculpt(tool);
        throwInputError("--sculpt",
                        "expected grab, smooth, inflate or deflate, got '" + options.sculpt + "'");
    });
    step(!options.surface.empty(), [&] { ui.setSurface(options.surface); });
    step(!options.merged.empty(), [&] { ui.setMergedDisplay(options.merged); });
    if (options.play >= 0.0) ui.startPlayback(options.play, options.sequence);
    step(!options.mapStart.empty(), [&] { ui.startMapFrom(options.mapStart); });
    step(!options.say.empty(), [&] {
        SpeechSettings speech = session.document().speech;
        speech.text = options.say;
        session.speech().setSettings(speech);
        ui.startSay(std::max(options.sayAt, 0.0), options.sayAt >= 0.0);
    });
}

// Replaces the mouse state for this frame by a straight left-button drag: pressed from frame 1,
// moving until two frames before the last, released after (used to test painting end to end).
void scriptedDrag(const EditorOptions& options, int frame) {
    ImGuiIO& io = ImGui::GetIO();
    const int last = std::max(options.frames - 3, 2);
    const float t = std::clamp(static_cast<float>(frame - 1) / static_cast<float>(last - 1), 0.0f, 1.0f);
    io.MousePos = ImVec2(options.drag[0] + t * (options.drag[2] - options.drag[0]),
                         options.drag[1] + t * (options.drag[3] - options.drag[1]));
    io.MouseDown[0] = frame >= 1 && frame <= last;
}

constexpr double kMaxFramesPerSecond = 60.0;

void waitForFrameSlot(double frameStart) {
    const double left = frameStart + 1.0 / kMaxFramesPerSecond - glfwGetTime();
    if (left > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(left));
}

} // namespace

void saveBackBufferPng(const std::filesystem::path& file, int width, int height, int bitsPerChannel) {
    std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    const std::size_t row = static_cast<std::size_t>(width) * 3;
    std::vector<unsigned char> flipped(pixels.size());
    for (int y = 0; y < height; ++y)
        std::copy_n(pixels.begin() +
                        static_cast<std::ptrdiff_t>(static_cast<std::size_t>(height - 1 - y) * row),
                    row, flipped.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(y) * row));
    // Fewer levels per channel compress far better (documentation pictures); 8 keeps every value.
    if (bitsPerChannel < 8) {
        const int drop = 8 - std::clamp(bitsPerChannel, 1, 8);
        for (unsigned char& c : flipped)
            c = static_cast<unsigned char>(((c >> drop) << drop) | ((c >> drop) << drop) >> (8 - drop));
    }
    stbi_write_png_compression_level = 9;
    if (!stbi_write_png(file.string().c_str(), width, height, 3, flipped.data(), static_cast<int>(row)))
        throw std::runtime_error(file.string() + ": cannot write the PNG");
}

int runEditor(const EditorOptions& options) {
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        std::fprintf(stderr,
                     "visemelab-editor: no display: run under xvfb-run or use the visemelab CLI (%s)\n",
                     lastGlfwError.c_str());
        return 1;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    GLFWwindow* window = glfwCreateWindow(options.width, options.height, "VisemeLab", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "visemelab-editor: cannot create an OpenGL 3.3 window: %s\n",
                     lastGlfwError.c_str());
        glfwTerminate();
        return 1;
    }
    glfwMakeContextCurrent(window);
    glfwSwapInterval(options.screenshot.empty() ? 1 : 0);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    float scale = contentScale(window);
    setupFontsAndStyle(scale);
    installKeyPresses(window); // before the backend, which chains its callback to this one
    glfwSetWindowContentScaleCallback(window, onContentScale);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    int exitCode = 0;
    {
        EditorSession session;
        try {
            EditorUi ui(session, window);
            if (!options.probe.empty()) probe::enable(options.probe);
            const bool screenshotMode = !options.screenshot.empty();
            // A script asking for a picture must fail; a person gets the editor with the errors shown.
            applyStartOptions(options, session, ui, [&](const InputError& e) {
                if (screenshotMode) throw e;
                session.error(std::string("Start options: ") + e.what());
            });
            ui.startOptionsApplied();
            std::string shownTitle;
            for (int frame = 0; !glfwWindowShouldClose(window) || !ui.quitConfirmed(); ++frame) {
                const double frameStart = glfwGetTime();
                glfwPollEvents();
                if (const std::string title =
                        windowTitle(session.files().path(), session.history().modified());
                    title != shownTitle) {
                    glfwSetWindowTitle(window, title.c_str());
                    shownTitle = title;
                }
                if (screenshotMode) session.finishBackgroundWork(); // deterministic pictures
                if (std::exchange(contentScaleChanged, false) && contentScale(window) != scale) {
                    scale = contentScale(window);
                    setupFontsAndStyle(scale);
                    ImGui_ImplOpenGL3_DestroyFontsTexture();
                    ImGui_ImplOpenGL3_CreateFontsTexture();
                }
                ImGui_ImplOpenGL3_NewFrame();
                ImGui_ImplGlfw_NewFrame();
                if (options.drag.size() == 4) scriptedDrag(options, frame);
                ImGui::NewFrame();
                ui.frame();
                if (probe::enabled()) probe::endFrame(ui.probeSummary());
                ImGui::Render();
                int width = 0, height = 0;
                glfwGetFramebufferSize(window, &width, &height);
                glViewport(0, 0, width, height);
                glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
                glClear(GL_COLOR_BUFFER_BIT);
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
                if (const auto shot = probe::takeScreenshotRequest())
                    saveBackBufferPng(*shot, width, height); // a GUI test's picture of this frame
                if (screenshotMode && frame + 1 >= options.frames) {
                    saveBackBufferPng(options.screenshot, width, height, options.screenshotBits);
                    std::printf("%s\n", options.screenshot.string().c_str());
                    break;
                }
                glfwSwapBuffers(window);
                if (ui.quitConfirmed()) break;
                // At most kMaxFramesPerSecond where swaps do not wait for the display (Xvfb, some
                // drivers): a spinning loop would take every core from the background work.
                if (!screenshotMode) waitForFrameSlot(frameStart);
            }
        } catch (const InputError& e) {
            std::fprintf(stderr, "visemelab-editor: error: %s\n", e.what());
            exitCode = 3;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "visemelab-editor: %s\n", e.what());
            exitCode = 1;
        }
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return exitCode;
}

} // namespace vl::ui
