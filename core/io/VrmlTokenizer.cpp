#include "core/io/VrmlTokenizer.h"

#include "core/common/Error.h"

namespace vl::meshio {

namespace {

bool isSeparator(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == '\f' || c == '\v';
}
bool isBracket(char c) {
    return c == '{' || c == '}' || c == '[' || c == ']';
}

} // namespace

std::vector<VrmlToken> tokenizeVrml(std::string_view text, std::string_view source) {
    std::vector<VrmlToken> tokens;
    tokens.reserve(text.size() / 6);
    std::size_t line = 1;
    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '\n') ++line;
        if (isSeparator(c)) {
            ++i;
        } else if (c == '#') {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (isBracket(c)) {
            tokens.push_back({text.substr(i, 1), line});
            ++i;
        } else if (c == '"') {
            const std::size_t start = i;
            const std::size_t startLine = line;
            for (++i; i < text.size() && text[i] != '"'; ++i) {
                if (text[i] == '\\')
                    ++i; // \" and \\ escapes
                else if (text[i] == '\n')
                    ++line;
            }
            if (i >= text.size()) throwInputError(fileLine(source, startLine), "unterminated string");
            ++i;
            tokens.push_back({text.substr(start, i - start), startLine});
        } else {
            const std::size_t start = i;
            while (i < text.size() && !isSeparator(text[i]) && !isBracket(text[i]) && text[i] != '#' &&
                   text[i] != '"')
                ++i;
            tokens.push_back({text.substr(start, i - start), line});
        }
    }
    return tokens;
}

} // namespace vl::meshio
