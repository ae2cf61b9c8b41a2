#pragma once
// The designer's constraints as command-line flags, the same for `reduce`, `avatar reduce` and
// `say --avatar -m`: --pin NAME, --apart A,B, --together A,B (repeatable) and --max-error-mm X.
#include "core/reduce/ReductionConstraints.h"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace vl::cli {

struct ConstraintOptions {
    std::vector<std::string> pin;      // viseme names
    std::vector<std::string> apart;    // "a,b"
    std::vector<std::string> together; // "a,b"
    double maxErrorMm = 0;             // 0: no bound
    std::string closure;               // ReduceSettings::closure: "auto", "none" or a viseme name

    // The flags as names; throws a usage error for a pair that is not "A,B".
    ConstraintNames names() const;
};

// `closureDefault`: the --closure value when the flag is absent ("auto" for avatars, "none" else).
void addConstraintOptions(CLI::App& command, ConstraintOptions& options, const char* closureDefault);

// ReduceSettings::closure for the flag's value ("none" -> "").
std::string closureSetting(const ConstraintOptions& options);

} // namespace vl::cli
