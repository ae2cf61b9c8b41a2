#pragma once
// Where a value was read from ("freq.json:/map", a file name), kept for error messages only. It is
// not part of the value: two tables with the same entries are equal wherever they came from, so a
// struct holding a Provenance can still default its comparison.
#include <string>

namespace vl {

struct Provenance {
    std::string text; // may be empty

    friend bool operator==(const Provenance&, const Provenance&) { return true; }
};

} // namespace vl
