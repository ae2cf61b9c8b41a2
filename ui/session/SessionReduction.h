#pragma once
// The session's reduction facet: the curve's settings as undoable edits (target, constraints, rest
// model), and the reduction of the current document on a worker thread (ReductionService) with
// its automatic re-runs. Finished curves go to the document's memoized inputs (DocumentInputs),
// the one home of the curve, its groupings and the reduced model.
#include "core/document/Document.h"
#include "ui/session/ReductionService.h"
#include "ui/session/SessionCore.h"

#include <cstdint>
#include <optional>
#include <string>

namespace vl::ui {

class SessionReduction {
  public:
    explicit SessionReduction(SessionCore& core);

    void setTarget(int m);
    // Pins, apart and together pairs by viseme name (validated; saved in the project).
    void setConstraints(ConstraintNames constraints);
    // The reduction model and rest viseme (edit::setRest), one undo step.
    void setRest(RestChoice rest, const std::string& restViseme);

    // Starts the reduction of the current inputs on a worker thread (no-op when already current).
    void start() { service_.start(core_.document(), core_.inputs()); }
    bool running() const { return service_.running(); }
    // Drops a running reduction (the searches stop within one progress poll); "Run now" restarts it.
    void cancel() { service_.cancel(); }
    // The panel's Cancel: a large set's branch and bound stops within one progress poll and its best
    // groupings are kept with their proven gaps; a small set's exact run is dropped.
    void stop() { service_.stop(); }
    double progress() const { return service_.progress(); }
    std::optional<double> secondsLeft() const { return service_.secondsLeft(); }
    std::optional<ReductionService::Bound> bound() const { return service_.bound(); }
    // The curve if it is up to date with the inputs, else null (DocumentInputs::curve).
    const ReductionResult* curve() const { return core_.inputs().curve(); }
    // Changes with every curve (DocumentInputs::curveRevision).
    std::uint64_t curveRevision() const { return core_.inputs().curveRevision(); }
    // Grouping into the target number of groups from the current curve, or null.
    const Grouping* grouping() const { return core_.inputs().grouping(); }
    // The reduced model of grouping() (merged keys, phoneme -> key; memoized), or null without a
    // grouping. Throws InputError when it cannot be built (DocumentInputs::reducedModel).
    const ReducedModel* reducedModel() const { return core_.inputs().reducedModel(); }
    // Re-run in the background after every input change (on by default).
    bool automatic() const { return automatic_; }
    void setAutomatic(bool on) { automatic_ = on; }

    // For the session: a curve a loaded project recorded, collecting
    // finished runs and starting automatic ones (once per frame), waiting for the worker.
    void seed(const LoadedProject& loaded);
    void poll();
    void wait() { service_.wait(); }

  private:
    SessionCore& core_;
    ReductionService service_;
    bool automatic_ = true;
};

} // namespace vl::ui
