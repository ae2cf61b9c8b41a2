#include "ui/session/SessionWeights.h"

#include "core/document/Commands.h"

namespace vl::ui {

void SessionWeights::setMode(WeightMode mode) {
    if (mode == core_.document().weights.mode) return;
    core_.commit(std::string("Weights: ") + toString(mode), edit::setWeightMode(core_.document(), mode));
}

void SessionWeights::setPainted(std::vector<double> painted, const std::string& actionName) {
    core_.commit(actionName, edit::setPaintedWeights(core_.document(), std::move(painted)));
}

} // namespace vl::ui
