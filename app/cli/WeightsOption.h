#pragma once
// The --weights option of reduce and avatar reduce: uniform, area, or a file of painted weights.
#include "core/reduce/ReduceRun.h"

#include <string>

namespace vl::cli {

// Sets settings.weightMode (and the painted weights and their source); "painted" without a file is
// a usage error.
void applyWeightsOption(const std::string& weights, ReduceSettings& settings);

} // namespace vl::cli
