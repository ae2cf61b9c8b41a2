// visemelab._core: the VisemeLab core for Python (the package visemelab wraps it).
#include "app/python/src/Bindings.h"
#include "app/python/src/Errors.h"

PYBIND11_MODULE(_core, m) {
    m.doc() = "VisemeLab's core: viseme reduction, avatar reduction, speech, batches";
    m.attr("__version__") = VISEMELAB_VERSION;
    vl::python::registerErrors(m);
    vl::python::bindVisemes(m);
    vl::python::bindAvatar(m);
    vl::python::bindSay(m);
    vl::python::bindBatch(m);
}
