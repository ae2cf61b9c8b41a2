#pragma once
// One way an enum meets text (project files, reports, command-line options): a table of
// {value, name} per enum, declared beside the enum as a specialisation of EnumNames, and these
// functions over it. Names are what files store and options accept, so a table is changed only
// with a project version (docs/project-format.md).
//
//   template <> struct EnumNames<Falloff> {
//       static constexpr const char* what = "falloff"; // the noun of an error message
//       static constexpr EnumName<Falloff> names[] = {{Falloff::Linear, "linear"}, ...};
//   };
//
//   toString(Falloff::Linear)                  // "linear"
//   fromString<Falloff>("cosine")              // Falloff::Cosine, or nullopt for anything else
//   parseEnum<Falloff>(text, "/fields/0")      // or InputError "/fields/0: unknown falloff 'x'
//                                              //   (expected linear, smoothstep, cosine or gaussian)"
#include "core/common/Error.h"

#include <concepts>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>

namespace vl {

template <class E> struct EnumName {
    E value;
    const char* name;
};

// Specialised for each enum that has names (see above); never defined for the others.
template <class E> struct EnumNames;

template <class E>
concept NamedEnum = requires {
    { EnumNames<E>::what } -> std::convertible_to<const char*>;
    EnumNames<E>::names[0].name;
};

// The name of `value`; "?" for a value outside the table (a cast from a bad integer).
template <NamedEnum E> constexpr const char* toString(E value) {
    for (const EnumName<E>& entry : EnumNames<E>::names)
        if (entry.value == value) return entry.name;
    return "?";
}

// The value named `text` (exact, case-sensitive), or nullopt.
template <NamedEnum E> constexpr std::optional<E> fromString(std::string_view text) {
    for (const EnumName<E>& entry : EnumNames<E>::names)
        if (text == entry.name) return entry.value;
    return std::nullopt;
}

// "a, b or c": the accepted names, in table order, for messages and option help.
template <NamedEnum E> std::string enumNameList(std::string_view lastSeparator = " or ") {
    std::string list;
    const auto& names = EnumNames<E>::names;
    const std::size_t count = std::size(names);
    for (std::size_t k = 0; k < count; ++k) {
        if (k > 0) list += k + 1 == count ? std::string(lastSeparator) : std::string(", ");
        list += names[k].name;
    }
    return list;
}

// The value named `text`; throws InputError "<where>: unknown <what> '<text>' (expected <names>)".
template <NamedEnum E> E parseEnum(std::string_view text, std::string_view where) {
    if (const std::optional<E> value = fromString<E>(text)) return *value;
    throwInputError(where, "unknown " + std::string(EnumNames<E>::what) + " '" + quoteInput(text) +
                               "' (expected " + enumNameList<E>() + ")");
}

} // namespace vl
