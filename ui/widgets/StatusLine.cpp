#include "ui/widgets/StatusLine.h"

namespace vl::ui {

const StatusMessage* StatusLine::update(const StatusMessage* newest, double now, bool hovered) {
    if (!newest) return nullptr;
    if (newest->serial != serial_) {
        serial_ = newest->serial;
        shownSince_ = now;
        expired_ = false;
    }
    if (expired_) return nullptr;
    if (hovered) shownSince_ = now;
    const double lifetime = newest->kind == StatusMessage::Kind::Error ? kErrorSeconds : kInfoSeconds;
    if (now - shownSince_ > lifetime) {
        expired_ = true;
        return nullptr;
    }
    return newest;
}

} // namespace vl::ui
