#include "core/common/JsonParse.h"

#include "core/common/Error.h"
#include "core/common/JsonDomBuilder.h"
#include "core/common/Limits.h"

#include <vector>

namespace vl {

namespace {

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
    JsonDomBuilder builder(source);
    try {
        Json::sax_parse(text.begin(), text.end(), &builder);
    } catch (const std::bad_alloc&) {
        throwInputError(source, "not enough memory to read this JSON document (" +
                                    std::to_string(text.size()) + " bytes)");
    }
    return builder.take();
}

std::string quoteJson(const Json& value) {
    return quoteInput(value.dump(-1, ' ', false, Json::error_handler_t::replace));
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
    const std::string capped = key.size() > kMaxQuotedInput ? quoteInput(key) : std::string();
    for (const char c : capped.empty() ? key : std::string_view(capped)) {
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
