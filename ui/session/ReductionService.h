#pragma once
// The reduction of the current document, as a background job. The curve (every p = 1..n) depends
// only on the document's reduction inputs (meshes, frequencies, weights, constraints, rest model):
// a run is tagged with their revision (DocumentInputs::reductionRevision) and its curve goes to
// DocumentInputs, where the groupings and reduced models derive from it.
#include "core/document/Document.h"
#include "core/document/DocumentInputs.h"
#include "core/project/ReduceInputs.h"
#include "core/reduce/Reduction.h"
#include "ui/session/BackgroundTask.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

class ReductionService {
  public:
    ~ReductionService() { task_.cancel(); }

    // Starts the reduction of the document on a worker thread (no-op when `inputs` hold a complete
    // curve or one is already being computed for their revision), with its memoized weights and
    // frequencies. Throws InputError when the document cannot be reduced.
    void start(const Document& document, const DocumentInputs& inputs);
    bool running() const { return task_.running(); }
    std::optional<double> secondsLeft() const { return task_.secondsLeft(); }
    double progress() const { return task_.progress(); }
    // True when a run for reduction inputs of this revision ended (an automatic re-run would only
    // repeat it, e.g. a failure).
    bool ranFor(std::uint64_t inputsRevision) const {
        return runningRevision_ == inputsRevision && !task_.running();
    }
    // A finished run: its curve and the inputs revision it was computed for, or its error.
    struct Outcome {
        std::shared_ptr<const ReductionResult> curve;
        std::uint64_t inputsRevision = 0;
        std::string error; // set when the run failed
    };
    // Collects a finished run (the owner pushes its curve into DocumentInputs::setCurve).
    std::optional<Outcome> poll();
    // Discards a running reduction.
    void cancel() { task_.cancel(); }
    // The Cancel button: a large set's branch and bound stops and its best groupings are kept with
    // their proven gaps (as at the time limit); a small set's exact run is cancelled.
    void stop();
    // The running branch and bound's proof for the target m: lower bound and best found so far
    // (null when no branch and bound runs or nothing was found yet).
    struct Bound {
        int groups = 0;
        double lowerBound = 0.0, bestFound = 0.0;
    };
    std::optional<Bound> bound() const;
    void wait() { task_.wait(); }

    // True when `inputs` hold a curve for the current inputs that reaches curveLength (a recorded
    // curve may stop at the project's m).
    static bool complete(const Document& document, const DocumentInputs& inputs) {
        return inputs.curve() && inputs.curve()->curve.size() >= curveLength(document);
    }
    // Entries of a full curve: p = 1..n, or up to the most keys the constraints and the rest model
    // allow (documentMaxKeys).
    static std::size_t curveLength(const Document& document);
    // How long a reduction may search before it reports the best grouping found with its gap (sets
    // of more than kMaxExactVisemes visemes): the editor's, which its exports use too.
    static ReducePolicy policy() { return ReducePolicy::interactive(); }

  private:
    std::uint64_t runningRevision_ = 0;
    BackgroundTask<std::shared_ptr<const ReductionResult>> task_;
    std::shared_ptr<BoundWatch> watch_;       // of the running task
    std::shared_ptr<std::atomic<bool>> stop_; // of the running task
    bool runningLarge_ = false;               // the running task is a branch and bound
};

} // namespace vl::ui
