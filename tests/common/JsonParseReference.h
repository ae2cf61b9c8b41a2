#pragma once
// The strict parser as it was before the linear one (nlohmann's callback parser and a std::set of
// keys per object): slow on large documents, but simple enough to trust. Kept only to check the
// linear parser against on small random documents.
#include "core/common/Error.h"
#include "core/common/JsonParse.h"
#include "core/common/Limits.h"

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace vl::test {

class ReferencePathTracker {
  public:
    explicit ReferencePathTracker(std::string_view source) : source_(source) {}

    bool onEvent(Json::parse_event_t event, const Json& parsed) {
        switch (event) {
        case Json::parse_event_t::object_start:
            frames_.push_back({true, {}, {}, 0});
            break;
        case Json::parse_event_t::array_start:
            frames_.push_back({false, {}, {}, 0});
            break;
        case Json::parse_event_t::key: {
            Frame& top = frames_.back();
            top.currentKey = parsed.get<std::string>();
            if (!top.keys.insert(top.currentKey).second)
                throwInputError(std::string(source_) + ": " + currentPath(),
                                "duplicate key \"" + top.currentKey + "\"");
            break;
        }
        case Json::parse_event_t::object_end:
        case Json::parse_event_t::array_end:
            frames_.pop_back();
            elementDone();
            break;
        case Json::parse_event_t::value:
            elementDone();
            break;
        }
        return true;
    }

    std::string currentPath() const {
        std::string path;
        for (const Frame& f : frames_)
            path = f.isObject ? jsonPathAppend(path, f.currentKey) : jsonPathAppend(path, f.index);
        return path.empty() ? "/" : path;
    }

  private:
    struct Frame {
        bool isObject;
        std::set<std::string> keys;
        std::string currentKey;
        std::size_t index;
    };

    void elementDone() {
        if (!frames_.empty() && !frames_.back().isObject) ++frames_.back().index;
    }

    std::string_view source_;
    std::vector<Frame> frames_;
};

inline Json referenceParseJsonStrict(std::string_view text, std::string_view source) {
    checkJsonNesting(text, source, limits::kMaxJsonDepth);
    ReferencePathTracker tracker(source);
    const Json::parser_callback_t callback = [&tracker](int, Json::parse_event_t event, Json& parsed) {
        return tracker.onEvent(event, parsed);
    };
    try {
        return Json::parse(text.begin(), text.end(), callback);
    } catch (const Json::parse_error& e) {
        std::string message = e.what();
        if (const auto close = message.find("] ");
            message.starts_with("[json.exception") && close != std::string::npos)
            message.erase(0, close + 2);
        throwInputError(source, "invalid JSON: " + message);
    } catch (const Json::out_of_range& e) {
        std::string message = e.what();
        const auto quote = message.find('\'');
        const std::string literal =
            quote == std::string::npos ? "" : message.substr(quote + 1, message.rfind('\'') - quote - 1);
        throwInputError(std::string(source) + ": " + tracker.currentPath(),
                        "number out of range: " + literal);
    }
}

} // namespace vl::test
