#pragma once
// The status bar's message: the newest one the session posted, shown for a while and then gone, so
// a message never outlives what it was about. The clock starts when the message first shows (not
// when it was posted: a message posted while the window was busy still gets its full time) and
// stops while the pointer rests on the bar, so a message being read never vanishes.
#include "ui/session/EditorSession.h"

#include <cstdint>

namespace vl::ui {

class StatusLine {
  public:
    static constexpr double kInfoSeconds = 6.0;
    static constexpr double kErrorSeconds = 20.0; // errors stay longer: they need reading and acting on

    // Call once per frame with the newest message (null when there is none), the time now in seconds
    // and whether the pointer is on the bar; returns the message to show, or null once it expired.
    const StatusMessage* update(const StatusMessage* newest, double now, bool hovered);

  private:
    std::uint64_t serial_ = 0; // the message being timed
    double shownSince_ = 0.0;
    bool expired_ = false;
};

} // namespace vl::ui
