#include "core/common/JsonParse.h"

#include "core/common/Error.h"
#include "core/common/Limits.h"

#include <set>
#include <vector>

namespace vl {

namespace {

// The parser callback sees events, not paths: this rebuilds the path of the current element so a
// duplicate key, or a number the parser cannot hold, can be reported where it is.
class PathTracker {
  public:
    explicit PathTracker(std::string_view source) : source_(source) {}

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

    // Path of the element being parsed (after its key, for object members).
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

// Keys in a too-deep path are shown shortened: the path is there to find the place, not to quote it.
std::string_view shortKey(std::string_view key) {
    return key.size() > 40 ? key.substr(0, 40) : key;
}

} // namespace

void checkJsonNesting(std::string_view text, std::string_view source, std::size_t maxDepth) {
    struct Frame {
        bool isObject;
        bool expectingKey;
        std::size_t index;
        std::string_view key; // raw (escapes not decoded): only for the message
    };
    std::vector<Frame> frames;
    frames.reserve(maxDepth);
    std::size_t line = 1;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        switch (c) {
        case '"': {
            const std::size_t start = i + 1;
            for (++i; i < text.size() && text[i] != '"'; ++i)
                if (text[i] == '\\') ++i;
            if (i >= text.size()) return; // unterminated: the parser reports it with its position
            if (!frames.empty() && frames.back().expectingKey) {
                frames.back().key = text.substr(start, i - start);
                frames.back().expectingKey = false;
            }
            break;
        }
        case '\n':
            ++line;
            break;
        case '{':
        case '[':
            if (frames.size() >= maxDepth) {
                std::string path;
                for (const Frame& f : frames)
                    path = f.isObject ? jsonPathAppend(path, shortKey(f.key)) : jsonPathAppend(path, f.index);
                throwInputError(std::string(source) + ": " + (path.empty() ? "/" : path),
                                "JSON nested deeper than " + std::to_string(maxDepth) + " levels (line " +
                                    std::to_string(line) + ")");
            }
            frames.push_back({c == '{', c == '{', 0, {}});
            break;
        case '}':
        case ']':
            if (!frames.empty()) frames.pop_back();
            break;
        case ',':
            if (!frames.empty()) {
                if (frames.back().isObject)
                    frames.back().expectingKey = true;
                else
                    ++frames.back().index;
            }
            break;
        default:
            break;
        }
    }
}

Json parseJsonStrict(std::string_view text, std::string_view source) {
    if (text.size() > limits::kMaxJsonBytes)
        throwInputError(source, "JSON document too large (" + std::to_string(text.size()) +
                                    " bytes; the limit is " + std::to_string(limits::kMaxJsonBytes) + ")");
    checkJsonNesting(text, source, limits::kMaxJsonDepth);
    PathTracker tracker(source);
    const Json::parser_callback_t callback = [&tracker](int, Json::parse_event_t event, Json& parsed) {
        return tracker.onEvent(event, parsed);
    };
    try {
        return Json::parse(text.begin(), text.end(), callback);
    } catch (const Json::parse_error& e) {
        // Drop nlohmann's "[json.exception.parse_error.101] " prefix; keep "parse error at line L, column C:
        // ...".
        std::string message = e.what();
        if (const auto close = message.find("] ");
            message.starts_with("[json.exception") && close != std::string::npos)
            message.erase(0, close + 2);
        throwInputError(source, "invalid JSON: " + message);
    } catch (const Json::out_of_range& e) {
        // A literal such as 1e999 overflows a double; nlohmann reports it without a position.
        std::string message = e.what();
        const auto quote = message.find('\'');
        const std::string literal =
            quote == std::string::npos ? "" : message.substr(quote + 1, message.rfind('\'') - quote - 1);
        throwInputError(std::string(source) + ": " + tracker.currentPath(),
                        "number out of range: " + literal);
    } catch (const std::bad_alloc&) {
        throwInputError(source, "not enough memory to read this JSON document (" +
                                    std::to_string(text.size()) + " bytes)");
    }
}

std::string jsonTypeName(const Json& value) {
    switch (value.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::object:
        return "object";
    case Json::value_t::array:
        return "array";
    case Json::value_t::string:
        return "string";
    case Json::value_t::boolean:
        return "boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float:
        return "number";
    case Json::value_t::binary:
        return "binary";
    case Json::value_t::discarded:
        break;
    }
    return "invalid value";
}

std::string jsonPathAppend(std::string_view path, std::string_view key) {
    std::string result(path);
    result += '/';
    for (const char c : key) {
        if (c == '~')
            result += "~0";
        else if (c == '/')
            result += "~1";
        else
            result += c;
    }
    return result;
}

std::string jsonPathAppend(std::string_view path, std::size_t index) {
    return std::string(path) + "/" + std::to_string(index);
}

} // namespace vl
