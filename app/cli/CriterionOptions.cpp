#include "app/cli/CriterionOptions.h"

#include "core/common/Error.h"

namespace vl::cli {

void addCriterionOptions(CLI::App* cmd, CriterionOptions& o) {
    auto& s = o.settings;
    cmd->add_option("--criterion", o.criterion, "Adaptive refinement criterion: depth, normals or contour");
    cmd->add_option("--depth", s.depth.depth, "depth: levels of edge bisection")->capture_default_str();
    cmd->add_option("--angle", s.normals.dihedralAngleDeg, "normals: dihedral angle threshold, degrees")
        ->capture_default_str();
    cmd->add_option("--normal-angle", s.normals.normalAngleDeg,
                    "normals: threshold on the angle between averaged endpoint normals, degrees")
        ->capture_default_str();
    cmd->add_option("--avg-error", s.contour.averageError, "contour: average error threshold (model units)")
        ->capture_default_str();
    cmd->add_option("--max-error", s.contour.maximumError, "contour: maximum error threshold (model units)")
        ->capture_default_str();
    cmd->add_option("--samples", s.contour.samplesPerSide, "contour: samples per triangle side (n*n samples)")
        ->capture_default_str();
    cmd->add_option("--max-depth", s.maxDepth, "Deepest level any criterion refines to")
        ->capture_default_str();
    cmd->add_option("--base-resolution", o.baseResolution,
                    "Grid cells across the face domain of the base mesh")
        ->capture_default_str();
}

namespace {

CriterionSettings checked(CriterionSettings s) {
    try {
        validateCriterionSettings(s);
    } catch (const InputError& e) {
        throwInputError("criterion option", e.what());
    }
    return s;
}

} // namespace

CriterionSettings criterionSettingsOver(const CriterionOptions& o, const CriterionSettings& base,
                                        const CLI::App& cmd) {
    CriterionSettings s = base;
    const auto given = [&cmd](const char* name) { return cmd.count(name) > 0; };
    if (given("--criterion")) s.kind = parseEnum<CriterionKind>(o.criterion, "--criterion");
    if (given("--depth")) s.depth.depth = o.settings.depth.depth;
    if (given("--angle")) s.normals.dihedralAngleDeg = o.settings.normals.dihedralAngleDeg;
    if (given("--normal-angle")) s.normals.normalAngleDeg = o.settings.normals.normalAngleDeg;
    if (given("--avg-error")) s.contour.averageError = o.settings.contour.averageError;
    if (given("--max-error")) s.contour.maximumError = o.settings.contour.maximumError;
    if (given("--samples")) s.contour.samplesPerSide = o.settings.contour.samplesPerSide;
    if (given("--max-depth")) s.maxDepth = o.settings.maxDepth;
    return checked(s);
}

CriterionSettings criterionSettings(const CriterionOptions& o) {
    CriterionSettings s = o.settings;
    s.kind = parseEnum<CriterionKind>(o.criterion, "--criterion");
    return checked(s);
}

} // namespace vl::cli
