#pragma once
// A running job's line: a bar with its fraction (moving stripes when it reports none), the label with
// the percentage and the time left when known ("Refining 40 % - about 5 s left"), and a Cancel
// button beside it. The same widget in the status bar and in the panels, so every job reads alike.
#include <optional>
#include <string>

namespace vl::ui {

// `cancelLabel`: the button's ImGui label ("Cancel##refine"). `width`: the bar's (< 0: to the right
// edge minus the button). Returns true when Cancel was clicked.
bool jobProgress(const std::string& label, std::optional<double> fraction, std::optional<double> secondsLeft,
                 const char* cancelLabel, float width);

// "40 % - about 5 s left", "12 %", "" (none known); minutes past 90 s.
std::string jobProgressText(std::optional<double> fraction, std::optional<double> secondsLeft);

} // namespace vl::ui
