#pragma once
// The session's weight facet: the per-vertex weights of the reduction's error (eq. 5) as undoable
// edits, and their memoized values.
#include "core/document/Document.h"
#include "ui/session/SessionCore.h"

#include <string>
#include <vector>

namespace vl::ui {

class SessionWeights {
  public:
    explicit SessionWeights(SessionCore& core) : core_(core) {}

    void setMode(WeightMode mode);
    void setPainted(std::vector<double> painted, const std::string& actionName);
    // The current document's weights (memoized; throws InputError when invalid).
    const std::vector<double>& values() const { return core_.inputs().weights(); }

  private:
    SessionCore& core_;
};

} // namespace vl::ui
