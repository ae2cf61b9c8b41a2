#pragma once
// A one-line progress indicator on stderr, shown only when stderr is a terminal.
#include "core/reduce/Reduction.h"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace vl::cli {

class ProgressLine {
  public:
    explicit ProgressLine(std::string label) : label_(std::move(label)), enabled_(::isatty(2) != 0) {}
    ~ProgressLine() { finish(); }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    ProgressCallback callback() {
        if (!enabled_) return {};
        return [this](double fraction) {
            std::fprintf(stderr, "\r%s: %3d%%", label_.c_str(), static_cast<int>(fraction * 100 + 0.5));
            std::fflush(stderr);
            shown_ = true;
        };
    }
    void finish() {
        if (shown_) std::fprintf(stderr, "\r%*s\r", static_cast<int>(label_.size()) + 8, "");
        shown_ = false;
    }

  private:
    std::string label_;
    bool enabled_;
    bool shown_ = false;
};

} // namespace vl::cli
