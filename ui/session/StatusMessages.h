#pragma once
// The session's status messages (info and errors, the status bar's history), and attempt(): the one
// place where an action's exception becomes an error message naming the action.
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>

namespace vl::ui {

struct StatusMessage {
    enum class Kind { Info, Error } kind = Kind::Info;
    std::string text;
    std::uint64_t serial = 0; // 1, 2, ... in the order the session posted them
};

class StatusMessages {
  public:
    void info(std::string text) { post(StatusMessage::Kind::Info, std::move(text)); }
    void error(std::string text) { post(StatusMessage::Kind::Error, std::move(text)); }
    // Runs `action`; an exception becomes an error message "<what>: <reason>" and returns false.
    bool attempt(std::string_view what, const std::function<void()>& action);
    // The last kMaxMessages messages, oldest first.
    const std::deque<StatusMessage>& list() const { return messages_; }

    static constexpr std::size_t kMaxMessages = 200;

  private:
    void post(StatusMessage::Kind kind, std::string text);
    std::deque<StatusMessage> messages_;
    std::uint64_t serial_ = 0;
};

} // namespace vl::ui
