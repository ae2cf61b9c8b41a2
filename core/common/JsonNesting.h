#pragma once
// Nesting depth of a JSON text, measured by a scan that builds nothing, so that a parser that
// recurses per level (tinygltf's extras, any DOM) can be protected from stack exhaustion before
// it runs. Strings (and their escapes) are skipped; the text need not be valid JSON.
#include <cstddef>
#include <string_view>

namespace vl {

// The deepest nesting of '[' and '{' outside strings.
std::size_t jsonNestingDepth(std::string_view text);

// Throws InputError "<source>: JSON nested deeper than <maxDepth> levels (at byte N)" when the
// text goes deeper than `maxDepth` levels.
void checkJsonNesting(std::string_view text, std::size_t maxDepth, std::string_view source);

} // namespace vl
