#include "ui/session/SessionReduction.h"

#include "core/document/Commands.h"
#include "core/reduce/Reduction.h"

namespace vl::ui {

SessionReduction::SessionReduction(SessionCore& core) : core_(core) {}

void SessionReduction::setTarget(int m) {
    if (m == core_.document().target) return;
    core_.commit("Target m = " + std::to_string(m), edit::setTarget(core_.document(), m), "target");
}

void SessionReduction::setConstraints(ConstraintNames constraints) {
    if (constraints == core_.document().constraints) return;
    core_.commit("Constraints", edit::setConstraints(core_.document(), std::move(constraints)));
}

void SessionReduction::setRest(RestChoice rest, const std::string& restViseme) {
    const Document& document = core_.document();
    if (rest == document.rest && restViseme == document.restViseme) return;
    core_.commit(rest == RestChoice::Key    ? "Rest is a key"
                 : rest == RestChoice::Free ? "Rest free"
                                            : "Rest free with a rest viseme",
                 edit::setRest(document, rest, restViseme));
}

void SessionReduction::seed(const LoadedProject& loaded) {
    // The result the file recorded is shown until a fresh reduction replaces it.
    // (Only a result of the document's rest model: a file may record one of the other.)
    const Document& document = core_.document();
    if (const auto& stored = loaded.reduction; stored && !stored->curve.empty() &&
                                               static_cast<int>(stored->curve.size()) >= document.target &&
                                               stored->restFree == documentRestPose(document).free)
        core_.setCurve(std::make_shared<const ReductionResult>(*stored), core_.inputs().reductionRevision());
}

void SessionReduction::poll() {
    if (auto outcome = service_.poll()) {
        if (!outcome->error.empty())
            core_.messages().error("Reduction: " + outcome->error);
        else
            core_.setCurve(std::move(outcome->curve), outcome->inputsRevision);
    }
    const DocumentInputs& inputs = core_.inputs();
    const int n = static_cast<int>(core_.document().visemeCount());
    if (automatic_ && n >= 2 && n <= kMaxReductionVisemes &&
        !ReductionService::complete(core_.document(), inputs) &&
        !service_.ranFor(inputs.reductionRevision()) && !service_.running())
        core_.messages().attempt("Reduction", [this] { start(); });
}

} // namespace vl::ui
