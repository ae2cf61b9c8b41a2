#pragma once
// The reduction of the current document, as a background job with its result cache. The curve
// (every p = 1..n) depends only on the document's reduction inputs (meshes, frequencies,
// weights): the service numbers those inputs with a revision that changes whenever they change,
// and keeps the curve and the reduced model for the revision they were computed for.
#include "core/document/Document.h"
#include "core/document/DocumentInputs.h"
#include "core/project/ReduceInputs.h"
#include "core/reduce/ReducedModel.h"
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

    // Tells the service the revision of the current document's reduction inputs
    // (DocumentInputs::reductionRevision): a curve of another revision is not current.
    void track(std::uint64_t inputsRevision) { revision_ = inputsRevision; }

    // A curve known for the current inputs (e.g. the result a project file recorded).
    void seed(std::shared_ptr<const ReductionResult> curve) {
        curve_ = {std::move(curve), revision_, ++curves_};
    }

    // Starts the reduction of the document on a worker thread (no-op when the curve is current or
    // already being computed), with its memoized weights and frequencies. Throws InputError when the
    // document cannot be reduced.
    void start(const Document& document, const DocumentInputs& inputs);
    bool running() const { return task_.running(); }
    std::optional<double> secondsLeft() const { return task_.secondsLeft(); }
    double progress() const { return task_.progress(); }
    // True when the last run on the current inputs failed (an automatic re-run would fail again).
    bool failedOnCurrentInputs() const { return runningRevision_ == revision_ && !task_.running(); }
    // Collects a finished run; returns the error message of a failed one.
    std::optional<std::string> poll();
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

    // The curve if it is up to date with the inputs, else null. A seeded curve may stop before
    // p = n (a project records p = 1..m); complete() tells whether it reaches n.
    const ReductionResult* curve() const;
    // Numbers every curve the service ever held (1, 2, ...; 0 = none yet): a cache of what derives
    // from the curve keys on it (with the inputs revision), never on the curve's address.
    std::uint64_t curveRevision() const { return curve_.revision; }
    bool complete(const Document& document) const {
        return curve() && curve()->curve.size() >= curveLength(document);
    }
    // Entries of a full curve: p = 1..n, or up to the most keys the constraints and the rest model
    // allow (documentMaxKeys).
    static std::size_t curveLength(const Document& document);
    // How long a reduction may search before it reports the best grouping found with its gap (sets
    // of more than kMaxExactVisemes visemes): the editor's, which its exports use too.
    static ReducePolicy policy() { return ReducePolicy::interactive(); }
    // The grouping into m groups from the current curve, or null.
    const Grouping* grouping(int m) const;
    // The reduced model of grouping(document.target): merged keys (frequency-weighted means, eq. 19)
    // and the phoneme -> key map, from buildReducedModel as every other front end gets them; null
    // when there is no current grouping. Throws InputError when the model cannot be built (e.g. the
    // phoneme map names a viseme the set lacks).
    const ReducedModel* reducedModel(const Document& document);

  private:
    struct Curve {
        std::shared_ptr<const ReductionResult> result;
        std::uint64_t inputsRevision = 0; // of the inputs it was computed for
        std::uint64_t revision = 0;       // curveRevision()
    };
    std::uint64_t revision_ = 1;
    Curve curve_;
    std::uint64_t curves_ = 0; // curves held so far (the last one's revision)
    std::uint64_t runningRevision_ = 0;
    BackgroundTask<std::shared_ptr<const ReductionResult>> task_;
    std::shared_ptr<BoundWatch> watch_;       // of the running task
    std::shared_ptr<std::atomic<bool>> stop_; // of the running task
    bool runningLarge_ = false;               // the running task is a branch and bound
    // reducedModel() cache, keyed by the inputs revision, the curve and the number of groups.
    std::uint64_t modelRevision_ = 0;
    std::uint64_t modelCurve_ = 0;
    int modelGroups_ = 0;
    std::optional<ReducedModel> model_;
};

} // namespace vl::ui
