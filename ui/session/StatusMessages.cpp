#include "ui/session/StatusMessages.h"

#include <algorithm>
#include <cctype>
#include <exception>

namespace vl::ui {

void StatusMessages::post(StatusMessage::Kind kind, std::string text) {
    messages_.push_back({kind, std::move(text), ++serial_});
    if (messages_.size() > kMaxMessages) messages_.pop_front();
}

bool StatusMessages::attempt(std::string_view what, const std::function<void()>& action) {
    try {
        action();
        return true;
    } catch (const std::exception& e) {
        // "Constraints: constraints: ..." says the same thing twice: a message that starts with
        // the action's name keeps only its own.
        const std::string_view message = e.what();
        const bool named = message.size() > what.size() + 1 && message[what.size()] == ':' &&
                           std::equal(what.begin(), what.end(), message.begin(), [](char a, char b) {
                               return std::tolower(static_cast<unsigned char>(a)) ==
                                      std::tolower(static_cast<unsigned char>(b));
                           });
        std::string text = named ? std::string(message) : std::string(what) + ": " + std::string(message);
        text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
        error(std::move(text));
        return false;
    }
}

} // namespace vl::ui
