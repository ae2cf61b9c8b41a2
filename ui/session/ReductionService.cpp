#include "ui/session/ReductionService.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>

namespace vl::ui {

std::size_t ReductionService::curveLength(const Document& document) {
    return static_cast<std::size_t>(std::max(1, documentMaxKeys(document)));
}

void ReductionService::start(const Document& document, const DocumentInputs& inputs) {
    if (document.visemeCount() < 2) throwInputError("reduction", "load a viseme set with at least 2 visemes");
    const std::uint64_t revision = inputs.reductionRevision();
    if (complete(document, inputs)) return;
    if (task_.running() && runningRevision_ == revision) return;
    const int n = static_cast<int>(document.visemeCount());
    if (n > kMaxReductionVisemes)
        throwInputError("reduction", "the reduction handles at most " + std::to_string(kMaxReductionVisemes) +
                                         " visemes, the set has " + std::to_string(n));
    const std::vector<std::string> names = visemeNames(document);
    const ReductionConstraints constraints = resolveConstraints(document.constraints, names);
    const int groups = static_cast<int>(curveLength(document));
    // Large sets: branch and bound reports the best grouping found and its proven gap when the time
    // is up, instead of keeping the designer waiting.
    ReductionOptions options;
    options.timeLimitSeconds = policy().timeLimitFor(document.visemeCount());
    // The bound of the target's search, for the progress bar, and a stop that keeps what was found.
    auto watch = std::make_shared<BoundWatch>(std::clamp(document.target, 1, groups));
    auto stop = std::make_shared<std::atomic<bool>>(false);
    options.watch = watch.get();
    options.cancelled = stop.get();
    watch_ = watch;
    stop_ = stop;
    // The worker holds the document's immutable meshes (viewed, not copied) and its own copies of
    // the rest.
    auto set = document.visemes;
    auto frequencies = std::make_shared<std::vector<double>>(inputs.frequencies());
    auto weights = std::make_shared<std::vector<double>>(inputs.weights());
    const RestPose rest = documentRestPose(document); // views set's neutral, which the worker holds
    runningRevision_ = revision;
    runningLarge_ = n > kMaxExactVisemes;
    task_.start(
        "Reducing " + std::to_string(n) + " visemes",
        [set, frequencies, weights, groups, constraints, rest, options, watch, stop](const auto& progress) {
            std::vector<std::span<const Vec3>> rows;
            for (const auto& viseme : set->visemes) rows.emplace_back(viseme.positions);
            const ReductionProblem problem{ShapeView(std::span<const std::span<const Vec3>>(rows)),
                                           *frequencies,
                                           *weights,
                                           groups,
                                           constraints,
                                           rest};
            return std::make_shared<const ReductionResult>(reduceVisemes(problem, options, progress));
        });
}

void ReductionService::stop() {
    // Branch and bound returns its best groupings with their proven gaps; the exact DP (small sets,
    // seconds at most) has nothing to keep and is cancelled.
    if (task_.running() && stop_ && runningLarge_)
        stop_->store(true);
    else
        task_.cancel();
}

std::optional<ReductionService::Bound> ReductionService::bound() const {
    if (!task_.running() || !watch_ || !runningLarge_) return std::nullopt;
    const double best = watch_->bestFound.load(), lower = watch_->lowerBound.load();
    if (!std::isfinite(best)) return std::nullopt;
    return Bound{watch_->groups, std::min(lower, best), best};
}

std::optional<ReductionService::Outcome> ReductionService::poll() {
    auto outcome = task_.take();
    if (!outcome) return std::nullopt;
    if (outcome->index() == 1) return Outcome{nullptr, runningRevision_, std::get<1>(*outcome)};
    return Outcome{std::get<0>(*outcome), runningRevision_, {}};
}

} // namespace vl::ui
