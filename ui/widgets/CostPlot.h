#pragma once
// The reduction's cost curve as a plot a designer reads: axes with ticks and units, linear or
// logarithmic value axis, the chosen m marked, a readout of the point under the cursor.
#include <imgui.h>

#include <span>

namespace vl::ui {

struct CostPlotOptions {
    bool logarithmic = true; // values over decades: p = 1 is often 100x p = n-1
    const char* unit = "";   // suffix of the value ticks and the readout ("mm", "%")
    int marked = 0;          // 1-based index drawn highlighted (the target m); 0 = none
    // What p counts: groups, or keys beside the free rest (the rest-free model).
    const char* axis = "groups p";
};

// values[p-1] for p = 1..n (>= 0; zeros sit on the bottom of a logarithmic axis). Occupies `size`
// (width <= 0: the available width). Returns the 1-based index the user clicked, or 0.
int costPlot(const char* id, std::span<const double> values, const CostPlotOptions& options, ImVec2 size);

} // namespace vl::ui
