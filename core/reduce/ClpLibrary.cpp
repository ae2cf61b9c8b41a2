#include "core/reduce/ClpLibrary.h"

#include "core/common/Error.h"

#include <dlfcn.h>

#include <string>

namespace vl {

namespace {

template <typename Function>
void resolve(void* handle, const char* name, Function& target, std::string& missing) {
    target = reinterpret_cast<Function>(::dlsym(handle, name));
    if (!target) missing += std::string(missing.empty() ? "" : ", ") + name;
}

ClpLibrary load() {
    void* handle = nullptr;
    for (const char* name : {"libClp.so.1", "libClp.so"})
        if ((handle = ::dlopen(name, RTLD_NOW | RTLD_LOCAL)) != nullptr) break;
    if (!handle)
        throwInputError("libClp.so.1", "cannot load COIN-OR CLP, the LP solver of the reduction (Debian "
                                       "package coinor-libclp1): " +
                                           std::string(::dlerror()));
    ClpLibrary clp{};
    std::string missing;
    resolve(handle, "Clp_newModel", clp.newModel, missing);
    resolve(handle, "Clp_deleteModel", clp.deleteModel, missing);
    resolve(handle, "Clp_setLogLevel", clp.setLogLevel, missing);
    resolve(handle, "Clp_setPrimalTolerance", clp.setPrimalTolerance, missing);
    resolve(handle, "Clp_setDualTolerance", clp.setDualTolerance, missing);
    resolve(handle, "Clp_resize", clp.resize, missing);
    resolve(handle, "Clp_chgRowLower", clp.chgRowLower, missing);
    resolve(handle, "Clp_chgRowUpper", clp.chgRowUpper, missing);
    resolve(handle, "Clp_addColumns", clp.addColumns, missing);
    resolve(handle, "Clp_chgColumnUpper", clp.chgColumnUpper, missing);
    resolve(handle, "Clp_primal", clp.primal, missing);
    resolve(handle, "Clp_isProvenOptimal", clp.isProvenOptimal, missing);
    resolve(handle, "Clp_dualRowSolution", clp.dualRowSolution, missing);
    resolve(handle, "Clp_primalColumnSolution", clp.primalColumnSolution, missing);
    if (!missing.empty()) throwInputError("libClp.so.1", "COIN-OR CLP lacks " + missing);
    return clp; // the handle stays open for the life of the process
}

} // namespace

const ClpLibrary& clpLibrary() {
    static const ClpLibrary library = load();
    return library;
}

} // namespace vl
