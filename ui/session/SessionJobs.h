#pragma once
// The session's background jobs as one list for progress and Cancel: loading, refinement,
// reduction, phoneme count.
#include "ui/session/SessionFace.h"
#include "ui/session/SessionFiles.h"
#include "ui/session/SessionFrequencies.h"
#include "ui/session/SessionReduction.h"

#include <optional>
#include <string>
#include <vector>

namespace vl::ui {

class SessionJobs {
  public:
    enum class Job { Loading, Refinement, Reduction, PhonemeCount };
    struct JobStatus {
        Job job;
        std::string label;
        std::optional<double> fraction;    // none: the job reports no progress
        std::optional<double> secondsLeft; // estimated from the progress so far
    };

    SessionJobs(StatusMessages& messages, SessionFiles& files, SessionFace& face, SessionReduction& reduction,
                SessionFrequencies& frequencies)
        : messages_(messages), files_(files), face_(face), reduction_(reduction), frequencies_(frequencies) {}

    std::vector<JobStatus> running() const;
    // Stops `job` at once and leaves the document as it was. A reduction keeps its best groupings with
    // their proven gaps (SessionReduction::stop); the others' results are dropped.
    void cancel(Job job);

  private:
    StatusMessages& messages_;
    SessionFiles& files_;
    SessionFace& face_;
    SessionReduction& reduction_;
    SessionFrequencies& frequencies_;
};

} // namespace vl::ui
