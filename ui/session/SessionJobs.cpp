#include "ui/session/SessionJobs.h"

namespace vl::ui {

std::vector<SessionJobs::JobStatus> SessionJobs::running() const {
    std::vector<JobStatus> jobs;
    if (files_.loading()) jobs.push_back({Job::Loading, files_.loadingLabel(), std::nullopt, std::nullopt});
    if (const RefinementService& refinement = face_.refinement(); refinement.running()) {
        const double p = refinement.progress();
        jobs.push_back(
            {Job::Refinement, "Refining", p > 0 ? std::optional(p) : std::nullopt, refinement.secondsLeft()});
    }
    if (reduction_.running())
        jobs.push_back({Job::Reduction, "Reducing", reduction_.progress(), reduction_.secondsLeft()});
    if (frequencies_.countRunning())
        jobs.push_back({Job::PhonemeCount, "Transcribing", frequencies_.countProgress(),
                        frequencies_.countSecondsLeft()});
    return jobs;
}

void SessionJobs::cancel(Job job) {
    const char* what = "";
    switch (job) {
    case Job::Loading:
        if (!files_.loading()) return;
        files_.cancelLoad();
        what = "Loading cancelled: the document is unchanged";
        break;
    case Job::Refinement:
        if (!face_.refinement().running()) return;
        face_.refinement().cancel();
        what = "Refinement cancelled: the face keeps its mesh";
        break;
    case Job::Reduction:
        if (!reduction_.running()) return;
        reduction_.stop();
        what = "Reduction stopped";
        break;
    case Job::PhonemeCount:
        if (!frequencies_.countRunning()) return;
        frequencies_.cancelCount();
        what = "Phoneme count cancelled: the frequencies are unchanged";
        break;
    }
    messages_.info(what);
}

} // namespace vl::ui
