#include "core/common/JsonNesting.h"

#include "core/common/Error.h"

#include <string>

namespace vl {
namespace {

// Scans `text`; returns the byte offset where the depth first exceeds `limit` (text.size() if never)
// and the deepest level seen up to there.
std::size_t scan(std::string_view text, std::size_t limit, std::size_t& deepest) {
    std::size_t depth = 0;
    deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i; // the escaped character cannot end the string
            else if (c == '"')
                inString = false;
            continue;
        }
        if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > deepest) deepest = depth;
            if (depth > limit) return i;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return text.size();
}

} // namespace

std::size_t jsonNestingDepth(std::string_view text) {
    std::size_t deepest = 0;
    scan(text, static_cast<std::size_t>(-1), deepest);
    return deepest;
}

void checkJsonNesting(std::string_view text, std::size_t maxDepth, std::string_view source) {
    std::size_t deepest = 0;
    const std::size_t at = scan(text, maxDepth, deepest);
    if (at < text.size())
        throwInputError(source, "JSON nested deeper than " + std::to_string(maxDepth) + " levels (at byte " +
                                    std::to_string(at) + ")");
}

} // namespace vl
