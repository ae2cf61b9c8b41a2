#pragma once
// Adaptive refinement of the document's face (paper section 5) as a background job. The adaptive
// mesh lives between runs (the paper's dynamic mesh: re-adaptation splits and welds where the
// surface changed); only the worker touches it, one run at a time.
#include "core/adaptive/AdaptiveMesh.h"
#include "core/document/Document.h"
#include "ui/session/BackgroundTask.h"
#include "ui/session/FaceSamples.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

// What a refinement run produced.
struct RefinementReport {
    std::string action;
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::size_t verticesBefore = 0; // of the face mesh shown when the run started
    std::size_t trianglesBefore = 0;
    // The adaptive mesh the run started from (after = start + splits - welds); a new face or field
    // starts again from the base mesh. 0 for "for all visemes" (refined from scratch per pose).
    std::size_t verticesAtStart = 0;
    bool fromBaseMesh = false;
    int maxLevel = 0;
    AdaptStats stats;
    double milliseconds = 0.0;
};

enum class RefineAction {
    Refine,     // split where the criterion asks, for the current parameters
    Simplify,   // weld where the criterion allows
    Adapt,      // re-adapt after a parameter or threshold change (resample, weld, split)
    AllVisemes, // one mesh refined for every viseme pose (for an interpolable viseme set)
};

struct AdaptiveWork;

class RefinementService {
  public:
    RefinementService();
    ~RefinementService();

    // Starts a run on the document's face, cascade, parameters and thresholds (copied: later edits
    // do not reach the worker). `automatic` marks a re-adaptation that follows the document.
    // Throws InputError without a face or while a run is going on.
    void start(const Document& document, RefineAction action, bool automatic);
    bool running() const { return task_.running(); }
    void wait() { task_.wait(); }
    // "For all visemes" reports progress (and so stops within one pose's refinement); the others are
    // dropped when they end. The document keeps the mesh it had.
    void cancel() { task_.requestCancel(); }
    double progress() const { return task_.progress(); }
    std::optional<double> secondsLeft() const { return task_.secondsLeft(); }

    struct Finished {
        std::shared_ptr<const MeshData> domain;            // the refined (u,v) mesh
        std::shared_ptr<const DeformationCascade> cascade; // the cascade it was refined for
        std::shared_ptr<const FaceSamples> samples;        // that cascade sampled on `domain` (GPU)
        RefinementReport report;
        bool automatic = false;
    };
    // A finished run (or its error message), once.
    std::optional<std::variant<Finished, std::string>> take();

    // Whether `document` has the inputs of the last automatic re-adaptation (then its mesh is the
    // one to show, and no new run is needed).
    bool automaticInputsCurrent(const Document& document) const;

    const std::optional<RefinementReport>& last() const { return last_; }
    void setLast(RefinementReport report) { last_ = std::move(report); }
    void clearLast() { last_.reset(); }

  private:
    std::shared_ptr<AdaptiveWork> work_;
    // Inputs of the last automatic re-adaptation (held, so the cascade's address is never reused).
    std::shared_ptr<const DeformationCascade> autoCascade_;
    std::vector<double> autoParameters_;
    CriterionSettings autoSettings_;
    std::optional<RefinementReport> last_;
    BackgroundTask<Finished> task_; // last member: joined before the others are destroyed
};

} // namespace vl::ui
