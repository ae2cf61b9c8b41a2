#include "app/cli/WeightsOption.h"

#include "app/cli/Command.h"

namespace vl::cli {

void applyWeightsOption(const std::string& weights, ReduceSettings& settings) {
    if (const auto mode = fromString<WeightMode>(weights)) {
        settings.weightMode = *mode;
        if (*mode == WeightMode::Painted) throwUsage("painted weights need a file: --weights FILE");
    } else {
        settings.weightMode = WeightMode::Painted;
        settings.paintedWeights = loadWeightsFile(weights);
        settings.paintedWeightsSource = weights;
    }
}

} // namespace vl::cli
