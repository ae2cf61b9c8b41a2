#pragma once
// COIN-OR CLP's C interface, loaded on first use. Linking it would load CLP, CoinUtils, LAPACK, BLAS
// and gfortran into every VisemeLab process at start-up (about 2 ms per command, measured), for a
// solver that only reductions past the subset DP's range use.
#include <coin/Clp_C_Interface.h>

namespace vl {

struct ClpLibrary {
    decltype(&Clp_newModel) newModel;
    decltype(&Clp_deleteModel) deleteModel;
    decltype(&Clp_setLogLevel) setLogLevel;
    decltype(&Clp_setPrimalTolerance) setPrimalTolerance;
    decltype(&Clp_setDualTolerance) setDualTolerance;
    decltype(&Clp_resize) resize;
    decltype(&Clp_chgRowLower) chgRowLower;
    decltype(&Clp_chgRowUpper) chgRowUpper;
    decltype(&Clp_addColumns) addColumns;
    decltype(&Clp_chgColumnUpper) chgColumnUpper;
    decltype(&Clp_primal) primal;
    decltype(&Clp_isProvenOptimal) isProvenOptimal;
    decltype(&Clp_dualRowSolution) dualRowSolution;
    decltype(&Clp_primalColumnSolution) primalColumnSolution;
};

// The library's functions (loaded once, thread-safe). Throws InputError naming the library and the
// Debian package when it cannot be loaded.
const ClpLibrary& clpLibrary();

} // namespace vl
