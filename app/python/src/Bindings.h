#pragma once
// The parts of the module visemelab._core, one file each.
#include <pybind11/pybind11.h>

namespace vl::python {

void bindVisemes(pybind11::module_& m); // VisemeSet, load_visemes, reduce_visemes
void bindAvatar(pybind11::module_& m);  // reduce_avatar
void bindSay(pybind11::module_& m);     // say
void bindBatch(pybind11::module_& m);   // run_jobs

} // namespace vl::python
