#pragma once
// The side panel's tabs, by name: the View menu, the tab bar, --panel and the GUI probe.
#include <optional>
#include <string_view>

namespace vl::ui {

enum class Panel { Visemes, Frequencies, Weights, Deformation, Refinement, Reduction, Export, Count };

const char* panelName(Panel panel);                        // "Visemes", "Frequencies", ...
const char* panelLabel(Panel panel);                       // the tab's short label: "Visemes", "Freq.", ...
std::optional<Panel> panelFromName(std::string_view name); // case-insensitive

} // namespace vl::ui
