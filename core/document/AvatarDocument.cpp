#include "core/document/AvatarDocument.h"

#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/gltf/AvatarReduce.h"
#include "core/gltf/AvatarReport.h"
#include "core/gltf/AvatarRest.h"
#include "core/gltf/GltfDocument.h"
#include "core/reduce/ReducedModel.h"

#include <algorithm>

namespace vl {

DocumentAvatar loadDocumentAvatar(const std::filesystem::path& file, const std::string& pattern,
                                  const std::string& addedRest) {
    DocumentAvatar avatar;
    avatar.file = std::filesystem::absolute(file);
    avatar.pattern = pattern;
    auto gltf = std::make_shared<const GltfDocument>(loadGltfDocument(file));
    avatar.scan = std::make_shared<const AvatarScan>(scanAvatar(*gltf, {pattern, true, addedRest}));
    avatar.gltf = std::move(gltf);
    return avatar;
}

Document documentFromAvatar(DocumentAvatar avatar, const FrequencySource& oculusTable) {
    const AvatarScan& scan = *avatar.scan;
    if (scan.visemes.size() < 2) {
        std::string hint;
        for (const std::string& pattern : suggestedPatterns(scan))
            hint += (hint.empty() ? "; its targets match " : ", ") + ("'" + pattern + "'");
        throwInputError(avatar.file.string(), "needs at least 2 visemes, found " +
                                                  std::to_string(scan.visemes.size()) + " (" +
                                                  scan.selection + ")" + hint);
    }
    Document document;
    // The set lives in the scan: the document shares it, nothing is copied.
    document.visemes = std::shared_ptr<const VisemeSet>(avatar.scan, &avatar.scan->set);
    document.visemeFiles.assign(scan.visemes.size(), {});
    document.frequencies = defaultAvatarFrequencies(scan, oculusTable);
    document.target = std::max(1, static_cast<int>(scan.visemes.size()) / 2);
    document.avatar = std::move(avatar);
    validateDocument(document);
    return document;
}

Project newAvatarProject(const std::filesystem::path& file, const std::string& pattern,
                         const FrequencySource& oculusTable, bool addRest) {
    Document document = documentFromAvatar(loadDocumentAvatar(file, pattern), oculusTable);
    if (addRest && !avatarHasRest(*document.avatar.scan))
        document = edit::addAvatarRestViseme(document, oculusTable);
    return projectFromDocument(document);
}

std::string reducedAvatarGlb(const Document& document, const std::vector<int>& groupOf,
                             const AvatarWriteOptions& options, AvatarWriteSummary* summary) {
    if (!document.avatar.isSet() || !document.visemes)
        throwInputError("export avatar", "the document has no avatar: use File > Import avatar... first");
    if (groupOf.size() != document.visemeCount())
        throwInputError("export avatar", "a grouping of " + std::to_string(groupOf.size()) + " visemes for " +
                                             std::to_string(document.visemeCount()));
    const std::vector<double> frequencies = documentFrequencies(document);
    const ReducedModel model =
        buildReducedModel(*document.visemes, frequencies, groupOf, document.frequencies);
    return writeReducedAvatar(*document.avatar.gltf, *document.avatar.scan, model, groupOf, frequencies,
                              options, summary);
}

void checkAvatarOutput(const Document& document, const std::filesystem::path& out) {
    if (!document.avatar.isSet())
        throwInputError("export avatar", "the document has no avatar: use File > Import avatar... first");
    std::error_code error, error2;
    const auto target = std::filesystem::weakly_canonical(out, error);
    if (std::filesystem::equivalent(out, document.avatar.file, error2) ||
        (!error && target == std::filesystem::weakly_canonical(document.avatar.file, error2)))
        throwInputError(out.string(), "is the avatar the document was read from; choose another file");
    if (out.extension() == ".gltf")
        throwInputError(out.string(), "the reduced avatar is written as binary glTF: name it .glb (or .vrm)");
}

} // namespace vl
