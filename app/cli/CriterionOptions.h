#pragma once
// Command-line options of the adaptive-mesh criteria, shared by `refine` and `visemes`.
#include "core/adaptive/Criteria.h"

#include <CLI/CLI.hpp>

#include <string>

namespace vl::cli {

struct CriterionOptions {
    std::string criterion;   // depth, normals, contour (empty: the command's default)
    int baseResolution = 10; // grid cells across the face domain of the base mesh
    CriterionSettings settings;
};

// Adds --criterion, --depth, --angle, --normal-angle, --avg-error, --max-error, --samples,
// --max-depth and --base-resolution.
void addCriterionOptions(CLI::App* cmd, CriterionOptions& options);

// The settings with the parsed kind (InputError naming the flag for bad values).
CriterionSettings criterionSettings(const CriterionOptions& options);

// `base` (e.g. a project's refinement settings) with the criterion options given on `cmd`'s command
// line in place of its values; checked like criterionSettings.
CriterionSettings criterionSettingsOver(const CriterionOptions& options, const CriterionSettings& base,
                                        const CLI::App& cmd);

} // namespace vl::cli
