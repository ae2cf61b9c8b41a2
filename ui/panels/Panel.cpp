#include "ui/panels/Panel.h"

#include <algorithm>
#include <cctype>

namespace vl::ui {
namespace {

// Tab labels are short so all seven fit; the full names are used by --panel and the View menu.
constexpr const char* kPanelLabels[] = {"Visemes", "Freq.",  "Weights", "Deform",
                                        "Refine",  "Reduce", "Export"};
constexpr const char* kPanelNames[] = {"Visemes",    "Frequencies", "Weights", "Deformation",
                                       "Refinement", "Reduction",   "Export"};

} // namespace

const char* panelName(Panel panel) {
    return kPanelNames[static_cast<int>(panel)];
}

const char* panelLabel(Panel panel) {
    return kPanelLabels[static_cast<int>(panel)];
}

std::optional<Panel> panelFromName(std::string_view name) {
    for (int i = 0; i < static_cast<int>(Panel::Count); ++i) {
        const std::string_view candidate = kPanelNames[i];
        if (candidate.size() == name.size() &&
            std::equal(candidate.begin(), candidate.end(), name.begin(), [](char a, char b) {
                return std::tolower(static_cast<unsigned char>(a)) ==
                       std::tolower(static_cast<unsigned char>(b));
            }))
            return static_cast<Panel>(i);
    }
    return std::nullopt;
}

} // namespace vl::ui
