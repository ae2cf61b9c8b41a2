#include "core/export/KeyMeshFiles.h"

#include "core/common/Error.h"
#include "core/common/FileNames.h"
#include "core/io/MeshIO.h"

namespace vl {

std::string neutralFileName(std::string_view extension) {
    return "neutral" + std::string(extension);
}

std::string keyFileName(const ReducedModel& model, std::size_t key, std::string_view extension) {
    return "reduced_" + std::to_string(key) + "_" + fileSafeName(model.keys[key].name) +
           std::string(extension);
}

std::vector<std::string> addKeyMeshFiles(OutputSet& outputs, const ReducedModel& model,
                                         std::string_view extension) {
    validateReducedModel(model, "export");
    std::vector<std::string> names{neutralFileName(extension)};
    // The keys share the neutral's topology; all are written as float32 (MeshIO.h, docs/export.md),
    // and coordinates a key shares with the neutral are formatted once.
    constexpr PositionPrecision kPrecision = PositionPrecision::Float32;
    const MeshTextFormatter formatter(names.back(), model.neutral, kPrecision);
    const PositionText neutral(model.neutral.positions, kPrecision);
    std::string text; // every file's positions; its faces and (u,v) are written from the formatter's text
    const auto add = [&](const PositionText& positions) {
        const MeshTextFormatter::Parts file = formatter.parts(positions, text);
        outputs.add(names.back(), {file.head, file.middle, file.tail});
    };
    add(neutral);
    PositionText positions;
    for (std::size_t k = 0; k < model.keys.size(); ++k) {
        names.push_back(keyFileName(model, k, extension));
        positions.assign(model.keys[k].positions, kPrecision, &neutral);
        add(positions);
    }
    return names;
}

std::vector<std::string> writeKeyMeshFiles(const std::filesystem::path& outDir, const ReducedModel& model,
                                           std::string_view extension) {
    OutputSet outputs(outDir, "export-" + std::string(extension.substr(extension.starts_with('.') ? 1 : 0)));
    std::vector<std::string> names = addKeyMeshFiles(outputs, model, extension);
    outputs.commit();
    return names;
}

} // namespace vl
