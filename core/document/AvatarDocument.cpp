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
    const std::vector<std::vector<Vec3>> sculpted = sculptedAvatarVisemes(document);
    AvatarWriteOptions withSculpts = options;
    if (!sculpted.empty()) withSculpts.sculpted = &sculpted;
    return writeReducedAvatar(*document.avatar.gltf, *document.avatar.scan, model, groupOf, frequencies,
                              withSculpts, summary);
}

std::vector<std::vector<Vec3>> sculptedAvatarVisemes(const Document& document) {
    if (!document.avatar.isSet() || !document.visemes) return {};
    const VisemeSet& file = document.avatar.scan->set;
    const VisemeSet& now = *document.visemes;
    if (&now == &file) return {}; // still the scan's own set: nothing sculpted
    std::vector<std::vector<Vec3>> sculpted(now.size());
    bool any = false;
    for (std::size_t i = 0; i < now.size() && i < file.size(); ++i)
        if (now.visemes[i].positions != file.visemes[i].positions) {
            sculpted[i] = now.visemes[i].positions;
            any = true;
        }
    if (!any) sculpted.clear();
    return sculpted;
}

std::vector<char> avatarSculptableVertices(const AvatarScan& scan, std::size_t viseme) {
    std::vector<char> movable(scan.set.neutral.positions.size(), 0);
    for (const AvatarMesh& mesh : scan.meshes) {
        if (!mesh.carriesVisemes) continue;
        const bool carries =
            std::any_of(mesh.targets.begin(), mesh.targets.end(),
                        [&](const AvatarTarget& t) { return t.viseme == static_cast<int>(viseme); });
        if (!carries) continue;
        for (const AvatarPrimitive& prim : mesh.primitives)
            std::fill_n(movable.begin() + static_cast<std::ptrdiff_t>(prim.firstVertex), prim.vertices, 1);
    }
    return movable;
}

void applyAvatarSculpts(Document& document, const std::vector<std::vector<Vec3>>& sculpted,
                        const std::string& where) {
    if (!document.avatar.isSet()) throwInputError(where, "the document has no avatar");
    const AvatarScan& scan = *document.avatar.scan;
    auto set = std::make_shared<VisemeSet>(scan.set);
    bool any = false;
    for (std::size_t i = 0; i < sculpted.size() && i < set->size(); ++i) {
        if (sculpted[i].empty()) continue;
        const std::string& name = set->visemes[i].name;
        const std::vector<Vec3>& file = scan.set.visemes[i].positions;
        if (sculpted[i].size() != file.size())
            throwInputError(where, name + ": " + std::to_string(sculpted[i].size()) +
                                       " positions, the avatar's " + "meshes carrying visemes have " +
                                       std::to_string(file.size()) + " vertices");
        const std::vector<char> movable = avatarSculptableVertices(scan, i);
        for (std::size_t v = 0; v < file.size(); ++v)
            if (!movable[v] && sculpted[i][v] != file[v])
                throwInputError(where, name + ": vertex " + std::to_string(v) +
                                           " moves, but its mesh has no target of " + name);
        set->visemes[i].positions = sculpted[i];
        any = true;
    }
    document.visemes = any ? std::shared_ptr<const VisemeSet>(std::move(set))
                           : std::shared_ptr<const VisemeSet>(document.avatar.scan, &scan.set);
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
