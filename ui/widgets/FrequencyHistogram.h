#pragma once
// The viseme frequencies as a bar chart a designer reads: one bar per viseme with its name centred
// under it (names too wide for their bar go on further rows, joined to the bar by a tick, so no
// name is cut or overlaps another), a value axis in % and the value of the bar under the cursor.
#include <imgui.h>

#include <span>
#include <string>

namespace vl::ui {

// How the names sit under n bars of `barWidth` pixels: the fewest rows such that names on one row
// never overlap (each row holds every rows-th name, centred under its bar, with `gap` pixels between
// neighbours on a row). Widths in pixels. At least 1.
int labelRows(std::span<const float> labelWidths, float barWidth, float gap);

// Draws the chart at the cursor, `height` pixels for the bars (the label rows come below) and the
// available width. `values` are >= 0 (normalised or not: shown as % of their sum).
void frequencyHistogram(const char* id, std::span<const double> values, std::span<const std::string> names,
                        float height);

} // namespace vl::ui
