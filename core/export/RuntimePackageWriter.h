#pragma once
// Writes a ReducedModel as a VisemeLab runtime package (docs/runtime-format.md), the compact
// little-endian binary that core/runtime loads on the device.
#include "core/reduce/ReducedModel.h"

#include <filesystem>
#include <string>

namespace vl {

struct RuntimePackageOptions {
    bool quantise = false; // 16-bit positions and displacements with per-axis offset/scale
};

// The package bytes. Throws InputError for a model the format cannot hold (validateReducedModel,
// counts above the format limits, a name longer than 65535 bytes).
std::string encodeRuntimePackage(const ReducedModel& model, const RuntimePackageOptions& options = {});

// encodeRuntimePackage, written atomically.
void writeRuntimePackage(const std::filesystem::path& path, const ReducedModel& model,
                         const RuntimePackageOptions& options = {});

} // namespace vl
