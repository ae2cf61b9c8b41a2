#include "ui/probe/GuiProbe.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace vl::ui::probe {
namespace {

struct Item {
    std::string label, kind, window;
    float x = 0, y = 0, width = 0, height = 0;
    bool visible = false, open = false;
    bool cut = false; // the whole item (its label too) reaches past its window's clip rectangle sideways
};

bool cutSideways(const ImRect& whole, const ImRect& clip) {
    // A selectable spans its row into half the item spacing on each side (ImGui draws its text
    // inside): that much is not a cut.
    const float slack = 0.5f * ImGui::GetStyle().ItemSpacing.x + 0.5f;
    return whole.Min.x < clip.Min.x - slack || whole.Max.x > clip.Max.x + slack;
}

struct Probe {
    bool enabled = false;
    std::filesystem::path file;
    std::vector<Item> items;                                       // this frame
    std::set<std::pair<const void*, ImGuiID>> ids;                 // (window, ID) this frame
    std::vector<std::string> duplicates;                           // labels whose ID was taken
    std::map<std::tuple<std::string, std::string>, Item> lastSeen; // (window, label) -> rectangle
    long frame = 0;
};

Probe& probeState() {
    static Probe probe;
    return probe;
}

// The text ImGui shows for a label ("Save##menu" shows "Save"; "###id" hides everything after).
std::string shownText(const char* label) {
    const std::string text(label);
    return text.substr(0, text.find("##"));
}

} // namespace

void enable(const std::filesystem::path& file) {
    probeState().enabled = true;
    probeState().file = file;
}

bool enabled() {
    return probeState().enabled;
}

Before before(const char* label) {
    if (!probeState().enabled) return {};
    ImGuiWindow* window = ImGui::GetCurrentContext()->CurrentWindow;
    return {window, window->GetIDNoKeepAlive(label)};
}

void recordItem(const Before& before, const char* label, const char* kind) {
    Probe& probe = probeState();
    if (!probe.enabled) return;
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const auto* window = static_cast<const ImGuiWindow*>(before.window);
    Item item;
    item.label = label;
    item.kind = kind;
    item.window = window->RootWindow ? window->RootWindow->Name : window->Name;
    // Two controls with one ID in a window share their state: ImGui 1.86 does not catch it (a
    // slider and a radio button both labelled "depth" crashed the editor), the probe reports it.
    if (!probe.ids.insert({window, before.id}).second)
        probe.duplicates.push_back(item.window + ": " + item.label);
    if (g.LastItemData.ID == before.id) {
        // The navigation rectangle: for sliders and other framed controls the frame (where a click
        // acts), not the label beside it; for the others the whole item.
        const ImRect& rect = g.LastItemData.NavRect;
        item.x = rect.Min.x;
        item.y = rect.Min.y;
        item.width = rect.GetWidth();
        item.height = rect.GetHeight();
        // Visible = inside the clip rectangle of its window (scrolled-out rows are not), or inside
        // the window's visible area: in a table the clip rectangle is one column's, and a row's
        // selectable spanning all columns has its centre outside the first column. (The menu bar
        // lies outside the visible area, inside its clip rectangle.)
        const ImVec2 centre = rect.GetCenter();
        item.visible = window->ClipRect.Contains(centre) || window->InnerClipRect.Contains(centre);
        // Cut: past both (a row's selectable spanning a table's columns passes its column's side).
        item.cut = cutSideways(g.LastItemData.Rect, window->ClipRect) &&
                   cutSideways(g.LastItemData.Rect, window->InnerClipRect);
        probe.lastSeen[{item.window, item.label}] = item;
    } else {
        // The popup of this combo or menu is open: the control is where it was last frame.
        const auto it = probe.lastSeen.find({item.window, item.label});
        if (it == probe.lastSeen.end()) return;
        item = it->second;
        item.open = true;
    }
    probe.items.push_back(std::move(item));
}

void recordArea(const char* label, const char* kind) {
    Probe& probe = probeState();
    if (!probe.enabled) return;
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    const ImGuiWindow* window = g.CurrentWindow;
    const ImRect& rect = g.LastItemData.Rect;
    probe.items.push_back({label, kind, window->RootWindow ? window->RootWindow->Name : window->Name,
                           rect.Min.x, rect.Min.y, rect.GetWidth(), rect.GetHeight(),
                           window->ClipRect.Contains(rect.GetCenter()), false,
                           cutSideways(rect, window->ClipRect)});
}

void recordRect(const char* label, const char* kind, ImVec2 min, ImVec2 max) {
    Probe& probe = probeState();
    if (!probe.enabled) return;
    const ImGuiWindow* window = ImGui::GetCurrentContext()->CurrentWindow;
    const ImRect rect(min, max);
    probe.items.push_back({label, kind, window->RootWindow ? window->RootWindow->Name : window->Name, min.x,
                           min.y, rect.GetWidth(), rect.GetHeight(),
                           window->ClipRect.Contains(rect.GetCenter()), false,
                           cutSideways(rect, window->ClipRect)});
}

std::optional<std::filesystem::path> takeScreenshotRequest() {
    const Probe& probe = probeState();
    if (!probe.enabled) return std::nullopt;
    const std::filesystem::path request = probe.file.string() + ".screenshot";
    std::FILE* f = std::fopen(request.string().c_str(), "rb");
    if (!f) return std::nullopt;
    char buffer[4096] = {};
    const std::size_t size = std::fread(buffer, 1, sizeof buffer - 1, f);
    std::fclose(f);
    std::error_code ignored;
    std::filesystem::remove(request, ignored);
    std::string path(buffer, size);
    while (!path.empty() && (path.back() == '\n' || path.back() == '\r')) path.pop_back();
    if (path.empty()) return std::nullopt;
    return std::filesystem::path(path);
}

void endFrame(const nlohmann::json& document) {
    Probe& probe = probeState();
    if (!probe.enabled) return;
    nlohmann::json controls = nlohmann::json::array();
    for (const Item& item : probe.items)
        controls.push_back({{"label", item.label},
                            {"text", shownText(item.label.c_str())},
                            {"kind", item.kind},
                            {"window", item.window},
                            {"x", item.x},
                            {"y", item.y},
                            {"width", item.width},
                            {"height", item.height},
                            {"visible", item.visible},
                            {"open", item.open},
                            {"cut", item.cut}});
    probe.items.clear();
    probe.ids.clear();
    nlohmann::json duplicates = std::move(probe.duplicates);
    probe.duplicates.clear();
    const ImGuiContext& g = *ImGui::GetCurrentContext();
    // The input this frame saw: a test waits for its events to arrive before the next one (the X
    // server and the editor may lag behind xdotool on a loaded machine).
    int keysDown = 0;
    for (const bool down : g.IO.KeysDown) keysDown += down ? 1 : 0;
    const nlohmann::json input = {{"x", g.IO.MousePos.x},
                                  {"y", g.IO.MousePos.y},
                                  {"buttons", {g.IO.MouseDown[0], g.IO.MouseDown[1], g.IO.MouseDown[2]}},
                                  {"keys_down", keysDown}};
    const nlohmann::json out = {{"frame", ++probe.frame},
                                {"input", input},
                                {"popup_open", !g.OpenPopupStack.empty()},
                                {"active_control", g.ActiveId != 0},
                                {"controls", std::move(controls)},
                                {"duplicate_ids", std::move(duplicates)},
                                {"document", document}};
    // Written every frame while a test watches: rename keeps each read whole; no fsync (a test file).
    const std::filesystem::path temporary = probe.file.string() + ".tmp";
    if (std::FILE* f = std::fopen(temporary.string().c_str(), "wb")) {
        const std::string text = out.dump();
        const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
        if (std::fclose(f) == 0 && written) {
            std::error_code ignored;
            std::filesystem::rename(temporary, probe.file, ignored);
        }
    }
}

} // namespace vl::ui::probe
