#pragma once
// Internal to the document commands (Commands.cpp, VisemeCommands.cpp, PhonemeMapCommands.cpp): the
// checks every command starts or ends with.
#include "core/common/Error.h"
#include "core/document/Document.h"

#include <string>
#include <string_view>

namespace vl::edit::detail {

// Every command ends here: the edited document must still reduce (frequencies resolve, weights
// valid, target in range, parameters in range).
inline Document checked(Document next) {
    validateDocument(next);
    return next;
}

// The same for an edit of `before`: only the checks that depend on what it changed (a slider tick
// checks the parameter values, not the frequencies and weights it left alone).
inline Document checkedChange(const Document& before, Document next) {
    validateDocument(next, changedParts(before, next));
    return next;
}

inline void requireSet(const Document& document, std::string_view what) {
    if (!document.visemes) throwInputError(what, "load a viseme set first");
}

// An avatar's visemes are its morph targets, chosen by the target pattern (edit::setAvatarPattern):
// they are not added, removed, renamed or reshaped one by one.
inline void refuseAvatar(const Document& document, std::string_view what) {
    if (document.avatar.isSet())
        throwInputError(what, "the visemes come from the avatar " + document.avatar.file.filename().string() +
                                  ": change which targets are visemes with the target pattern");
}

inline void requireFace(const Document& document, std::string_view what) {
    if (!document.face.cascade) throwInputError(what, "no face loaded");
}

inline std::size_t checkedIndex(int index, std::size_t size, std::string_view what) {
    if (index < 0 || static_cast<std::size_t>(index) >= size)
        throwInputError(what, "index " + std::to_string(index) + " is outside 0.." +
                                  std::to_string(static_cast<long long>(size) - 1));
    return static_cast<std::size_t>(index);
}

} // namespace vl::edit::detail
