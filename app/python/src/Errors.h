#pragma once
// How the core's errors reach Python: InputError (bad input, its message names the file and element)
// becomes visemelab.InputError with .culprit; a filesystem error becomes visemelab.InputError naming
// its path; anything else stays a RuntimeError (pybind11's default for std::exception).
#include <pybind11/pybind11.h>

#include <string>
#include <string_view>

namespace vl::python {

// The "<where>" of an InputError message "<where>: <what>" (throwInputError's layout): the file and
// element the message blames; the whole message when it has no such prefix.
std::string culpritOf(std::string_view message);

// Registers visemelab._core.InputError (a ValueError) and the translator.
void registerErrors(pybind11::module_& m);

} // namespace vl::python
