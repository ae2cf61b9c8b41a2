// Issue 14's small things with real clicks (xdotool on a private Xvfb, see GuiDriver.h): no control
// label cut at 1600x1000 or 1280x720, the frequency histogram's names, status messages that wrap
// and expire, the refine result's vertex counts, the (u,v) inset moved by its bar and edited in its
// square, the merged shape in error colours, skin or over the original.
#include "GuiDriver.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>

namespace vl::test {
namespace {

std::optional<nlohmann::json> statusControl(const GuiDriver& gui) {
    for (const auto& control : gui.report()["controls"])
        if (control["kind"] == "status") return control;
    return std::nullopt;
}

// Every tab at both window sizes: no visible control (label included) reaches past the side of its
// window, and the histogram's names lie inside the panel and apart from each other.
TEST(PolishClicks, NoLabelIsCutAtEitherWindowSize) {
    REQUIRE_GUI_TOOLS();
    for (const auto& [width, height] : {std::pair{1600, 1000}, std::pair{1280, 720}}) {
        SCOPED_TRACE(std::to_string(width) + "x" + std::to_string(height));
        GuiDriver gui({"--sample", "--panel", "Visemes"}, width, height);
        gui.waitIdle();
        for (const char* tab : {"Visemes", "Freq.", "Weights", "Deform", "Refine", "Reduce", "Export"}) {
            gui.click(gui.control(tab, "tab"));
            gui.waitIdle();
            EXPECT_ALIVE(gui);
            int labels = 0;
            for (const auto& control : gui.report()["controls"]) {
                if (!control["visible"].get<bool>()) continue;
                EXPECT_FALSE(control.value("cut", false))
                    << tab << ": '" << control["label"].get<std::string>() << "' (" << control["kind"]
                    << ") is cut at x " << control["x"] << " width " << control["width"];
                if (control["kind"] != "histogram-label") continue;
                ++labels;
                EXPECT_LE(control["x"].get<double>() + control["width"].get<double>(), width);
            }
            if (std::string(tab) == "Freq.") {
                EXPECT_EQ(labels, gui.document()["visemes"].get<int>()) << "one name per bar";
                // Names on one row do not overlap.
                std::vector<nlohmann::json> names;
                for (const auto& control : gui.report()["controls"])
                    if (control["kind"] == "histogram-label") names.push_back(control);
                for (std::size_t i = 0; i < names.size(); ++i)
                    for (std::size_t j = i + 1; j < names.size(); ++j) {
                        if (names[i]["y"] != names[j]["y"]) continue;
                        const double a0 = names[i]["x"].get<double>(),
                                     a1 = a0 + names[i]["width"].get<double>();
                        const double b0 = names[j]["x"].get<double>(),
                                     b1 = b0 + names[j]["width"].get<double>();
                        EXPECT_TRUE(a1 <= b0 || b1 <= a0)
                            << names[i]["label"] << " overlaps " << names[j]["label"];
                    }
            }
        }
    }
}

// A long error wraps inside the window (the bar grows) and stays; an info message goes after its
// time.
TEST(PolishClicks, StatusMessagesWrapAndExpire) {
    REQUIRE_GUI_TOOLS();
    const std::string longPath = "/nonexistent/" + std::string(150, 'x') + "/project.vlproj";
    GuiDriver gui({"--project", longPath}, 1280, 720);
    gui.waitIdle();
    auto status = statusControl(gui);
    ASSERT_TRUE(status) << gui.document()["messages"].dump();
    EXPECT_NE(status->value("label", "").find("project.vlproj"), std::string::npos);
    EXPECT_FALSE(status->value("cut", true)) << status->dump();
    EXPECT_GT((*status)["height"].get<double>(), 20.0)
        << "one line for a 200-character message: " << status->dump();
    // An info message (File > Load sample) replaces it and is gone some seconds later.
    gui.key("ctrl+l");
    gui.waitIdle();
    status = statusControl(gui);
    ASSERT_TRUE(status);
    EXPECT_NE(status->value("label", "").find("sample"), std::string::npos) << status->dump();
    // The pointer off the bar (resting on the bar holds the message: the driver parks it there).
    const auto view = gui.control("main", "view");
    gui.hover(view["x"].get<double>() + 0.5 * view["width"].get<double>(),
              view["y"].get<double>() + 0.5 * view["height"].get<double>());
    const auto start = std::chrono::steady_clock::now();
    while (statusControl(gui) && std::chrono::steady_clock::now() - start < std::chrono::seconds(30)) {
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
        gui.waitFrames(1);
    }
    EXPECT_FALSE(statusControl(gui)) << "the info message never expired: " << statusControl(gui)->dump()
                                     << "\n"
                                     << gui.document()["messages"].dump();
    EXPECT_ALIVE(gui);
}

// Refine: the panel's result in the probe, vertex counts before and after, added and removed.
TEST(PolishClicks, RefineStatesRefinedAndCoarsenedCounts) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Refinement"});
    gui.waitIdle();
    const auto before = documentRevision(gui);
    gui.click(gui.control("Refine", "button"));
    gui.waitIdle();
    EXPECT_ALIVE(gui);
    EXPECT_NE(documentRevision(gui), before);
    const auto refine = gui.document()["refine"];
    ASSERT_FALSE(refine.is_null()) << gui.document().dump();
    EXPECT_GT(refine["added"].get<int>(), 0);
    // The counts add up: each split adds a vertex, each weld removes one.
    EXPECT_EQ(refine["vertices_after"].get<int>(), refine["vertices_at_start"].get<int>() +
                                                       refine["added"].get<int>() -
                                                       refine["removed"].get<int>())
        << refine.dump();
    // A smaller maximum depth, then Simplify: vertices deeper than it are welded away.
    gui.click(gui.control("max depth", "slider"), 0.05);
    gui.waitIdle();
    gui.click(gui.control("Simplify", "button"));
    gui.waitIdle();
    const auto simplified = gui.document()["refine"];
    EXPECT_GT(simplified["removed"].get<int>(), 0) << simplified.dump();
    EXPECT_EQ(simplified["vertices_before"], refine["vertices_after"]) << simplified.dump();
    EXPECT_EQ(simplified["vertices_after"].get<int>(), simplified["vertices_at_start"].get<int>() +
                                                           simplified["added"].get<int>() -
                                                           simplified["removed"].get<int>());
    EXPECT_LT(simplified["vertices_after"].get<int>(), simplified["vertices_before"].get<int>());
}

// The (u,v) inset: its bar moves it (and it stays inside the view), its square moves the field.
TEST(PolishClicks, UvInsetMovesByItsBarAndEditsInItsSquare) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Deformation", "--field", "zygomatic_l"});
    gui.waitIdle();
    const auto bar = gui.control("##uv-title", "button");
    const double bx = bar["x"].get<double>() + 0.5 * bar["width"].get<double>();
    const double by = bar["y"].get<double>() + 0.5 * bar["height"].get<double>();
    const auto view = gui.control("main", "view");
    const auto before = documentRevision(gui);
    gui.drag(bx, by, bx - 300, by - 250, 10);
    const auto moved = gui.control("##uv-title", "button");
    EXPECT_NEAR(moved["x"].get<double>(), bar["x"].get<double>() - 300, 2.0);
    EXPECT_NEAR(moved["y"].get<double>(), bar["y"].get<double>() - 250, 2.0);
    EXPECT_EQ(documentRevision(gui), before) << "moving the inset is not an edit";
    // Far past the top-left corner: it stops at the view's edge.
    gui.drag(moved["x"].get<double>() + 20, moved["y"].get<double>() + 5, view["x"].get<double>() + 2,
             view["y"].get<double>() + 2, 10);
    const auto corner = gui.control("##uv-title", "button");
    EXPECT_GE(corner["x"].get<double>(), view["x"].get<double>() - 0.5);
    EXPECT_GE(corner["y"].get<double>(), view["y"].get<double>() - 0.5);
    // A drag in the square moves the field's centre: one undo step.
    const auto square = gui.control("##uv", "button");
    const double sx = square["x"].get<double>(), sy = square["y"].get<double>();
    const double side = square["width"].get<double>();
    gui.drag(sx + 0.5 * side, sy + 0.5 * side, sx + 0.3 * side, sy + 0.6 * side, 6);
    EXPECT_NE(documentRevision(gui), before);
    EXPECT_NE(gui.document()["undo"].get<std::string>().find("field"), std::string::npos)
        << gui.document().dump();
    EXPECT_ALIVE(gui);
}

// The merged shape: error colours, skin, overlay on the original, each a click.
TEST(PolishClicks, MergedShapeInSkinAndAsOverlay) {
    REQUIRE_GUI_TOOLS();
    GuiDriver gui({"--sample", "--panel", "Reduction"});
    gui.waitIdle();
    EXPECT_EQ(gui.document()["merged_display"], 0);
    gui.click(gui.reveal("skin", "radio"));
    EXPECT_EQ(gui.document()["merged_display"], 1);
    gui.click(gui.reveal("overlay on original", "radio"));
    EXPECT_EQ(gui.document()["merged_display"], 2);
    gui.click(gui.reveal("error colours", "radio"));
    EXPECT_EQ(gui.document()["merged_display"], 0);
    EXPECT_ALIVE(gui);
    // The start option (the guide's pictures use it); a wrong name is shown, not fatal.
    GuiDriver overlay({"--sample", "--panel", "Reduction", "--merged", "overlay"});
    overlay.waitIdle();
    EXPECT_EQ(overlay.document()["merged_display"], 2);
    GuiDriver wrong({"--sample", "--panel", "Reduction", "--merged", "nosuch"});
    wrong.waitIdle();
    EXPECT_ALIVE(wrong);
    EXPECT_EQ(wrong.document()["merged_display"], 0);
    const auto status = statusControl(wrong);
    ASSERT_TRUE(status);
    EXPECT_NE((*status)["label"].get<std::string>().find("--merged"), std::string::npos) << status->dump();
}

} // namespace
} // namespace vl::test
