#include "core/document/Document.h"

#include "core/common/Error.h"
#include "core/document/AvatarDocument.h"
#include "core/face/FaceDomain.h"
#include "core/gltf/AvatarScan.h"
#include "core/project/BuiltinGeometry.h"
#include "core/project/FaceProject.h"
#include "core/project/ProjectRun.h"

#include <atomic>

namespace vl {

const std::vector<double>& DocumentWeights::paintedOrEmpty() const {
    static const std::vector<double> none;
    return painted ? *painted : none;
}

bool sameReductionInputs(const Document& a, const Document& b) {
    return a.visemes == b.visemes && a.frequencies == b.frequencies && a.weights == b.weights &&
           a.constraints == b.constraints && a.rest == b.rest && a.restViseme == b.restViseme;
}

RestPose documentRestPose(const Document& document) {
    if (!document.visemes) return {};
    const int restViseme = restVisemeIndex(visemeNames(document), document.restViseme, "rest viseme");
    return {restIsFree(document.rest, restViseme), restViseme, document.visemes->neutral.positions};
}

int documentMaxKeys(const Document& document) {
    const std::vector<std::string> names = visemeNames(document);
    const int n = static_cast<int>(names.size());
    int groups = n;
    try {
        groups =
            std::min(n, constraintUnits(resolveConstraints(document.constraints, names), n, names).maxGroups);
    } catch (const InputError&) { // contradicting constraints: the reduction reports them
    }
    const RestPose rest = documentRestPose(document);
    // The rest viseme's group rests, so it is no key.
    return rest.free && rest.viseme >= 0 ? std::max(1, groups - 1) : groups;
}

std::vector<std::string> visemeNames(const Document& document) {
    std::vector<std::string> names;
    if (document.visemes)
        for (const Viseme& viseme : document.visemes->visemes) names.push_back(viseme.name);
    return names;
}

std::vector<double> documentWeights(const Document& document) {
    if (!document.visemes) return {};
    return computeWeights(document.weights.mode, document.visemes->neutral,
                          document.weights.paintedOrEmpty());
}

std::vector<double> documentFrequencies(const Document& document) {
    return visemeFrequencies(document.frequencies, visemeNames(document));
}

namespace {
std::atomic<std::uint64_t> inputValidations{0};
} // namespace

DocumentParts changedParts(const Document& before, const Document& after) {
    DocumentParts parts = 0;
    if (before.visemes != after.visemes || before.neutralFile != after.neutralFile ||
        before.visemeFiles != after.visemeFiles || before.visemeColours != after.visemeColours ||
        before.avatar != after.avatar)
        parts |= kVisemePart;
    if (before.frequencies != after.frequencies) parts |= kFrequencyPart;
    if (before.weights != after.weights) parts |= kWeightPart;
    if (before.face.parameters != after.face.parameters) parts |= kFaceParameterPart;
    if (before.face.cascade != after.face.cascade || before.face.individual != after.face.individual ||
        before.face.presets != after.face.presets)
        parts |= kFacePart;
    if (before.face.domain != after.face.domain) parts |= kFaceMeshPart;
    if (before.constraints != after.constraints || before.rest != after.rest ||
        before.restViseme != after.restViseme)
        parts |= kReductionPart;
    if (before.target != after.target) parts |= kTargetPart;
    if (before.refinement != after.refinement || before.speech != after.speech ||
        before.ownFace != after.ownFace)
        parts |= kOtherPart;
    // A field the tags above do not know yet (added later): everything may have changed.
    if (parts == 0 && !(before == after)) parts = kAllDocumentParts;
    return parts;
}

std::uint64_t reductionInputValidations() {
    return inputValidations.load();
}

void validateDocument(const Document& document, DocumentParts changed) {
    if (document.face.cascade && (changed & (kFaceParameterPart | kFacePart | kFaceMeshPart)))
        checkParameterValues(*document.face.cascade, document.face.parameters);
    constexpr DocumentParts reductionInputs =
        kVisemePart | kFrequencyPart | kWeightPart | kReductionPart | kTargetPart;
    if (!document.visemes || !(changed & reductionInputs)) return;
    ++inputValidations;
    if (document.visemeFiles.size() != document.visemes->size())
        throwInputError("document", "one mesh source per viseme expected");
    documentFrequencies(document);
    documentWeights(document);
    const std::vector<std::string> names = visemeNames(document);
    constraintUnits(resolveConstraints(document.constraints, names), static_cast<int>(names.size()), names);
    documentRestPose(document); // the rest viseme is one of the set
    const int n = static_cast<int>(document.visemes->size());
    if (document.target < 1 || document.target > n)
        throwInputError("target",
                        "m = " + std::to_string(document.target) + " is outside 1.." + std::to_string(n));
}

MeshData storedFaceDomain(const MeshData& domain) {
    MeshData stored = projectDomainMesh(domain);
    if (stored == face::faceDomainMesh(kFaceDomainResolution, face::DomainDensity::MouthFocused)) return {};
    return stored;
}

FaceModel makeFaceModel(face::Individual individual, int resolution) {
    FaceModel model;
    model.individual = individual;
    auto cascade = std::make_shared<DeformationCascade>(face::makeFaceCascade(individual));
    model.parameters = cascade->defaults();
    model.cascade = std::move(cascade);
    model.domain =
        std::make_shared<const MeshData>(face::faceDomainMesh(resolution, face::DomainDensity::MouthFocused));
    return model;
}

LoadedProject documentFromProject(const Project& project) {
    LoadedProject loaded;
    Document& document = loaded.document;
    if (project.avatar.isSet()) {
        // The meshes come from the avatar, read once; the project only names its visemes.
        try {
            document.avatar = loadDocumentAvatar(resolveProjectFile(project, project.avatar.file),
                                                 project.avatar.targets, project.avatar.addedRest);
        } catch (const InputError& e) {
            throwInputError((project.path.empty() ? "" : project.path.string() + ": ") + "/avatar/file",
                            e.what());
        }
        checkAvatarVisemeNames(project, document.avatar.scan->visemes);
        std::vector<std::vector<Vec3>> sculpted(project.visemes.size());
        for (std::size_t i = 0; i < project.visemes.size(); ++i) sculpted[i] = project.visemes[i].positions;
        applyAvatarSculpts(document, sculpted,
                           (project.path.empty() ? "" : project.path.string() + ": ") + "/visemes");
        document.visemeFiles.assign(project.visemes.size(), {});
    } else if (project.neutral.isSet()) {
        document.visemes = std::make_shared<const VisemeSet>(loadProjectVisemeSet(project));
        const auto absolute = [&](const std::filesystem::path& file) {
            return file.empty() ? file : std::filesystem::absolute(resolveProjectFile(project, file));
        };
        document.neutralFile = absolute(project.neutral.file);
        for (const ProjectViseme& viseme : project.visemes)
            document.visemeFiles.push_back(absolute(viseme.file));
    }
    document.frequencies = project.frequencies;
    document.weights.mode = project.weights.mode;
    if (!project.weights.painted.empty())
        document.weights.painted = std::make_shared<const std::vector<double>>(project.weights.painted);
    document.refinement = project.refinement;
    document.target = project.reduction.target;
    document.constraints = project.reduction.constraints;
    document.rest = project.reduction.rest;
    document.restViseme = project.reduction.restViseme;
    document.speech = project.speech;
    if (project.deformation.isSet()) {
        FaceModel& model = document.face;
        model.cascade = std::make_shared<const DeformationCascade>(project.deformation.cascade);
        // The retargeting choice is the base geometry the project saved (a built-in reference).
        model.individual = builtinIndividualOf(*model.cascade).value_or(face::Individual::Bundled);
        model.parameters = project.deformation.values;
        model.presets = project.deformation.visemes;
        // The (u,v) mesh the project stored (refined, or made by face build), else the default.
        model.domain = std::make_shared<const MeshData>(
            project.deformation.domain.positions.empty()
                ? face::faceDomainMesh(kFaceDomainResolution, face::DomainDensity::MouthFocused)
                : project.deformation.domain);
        // The face model defines the (u,v) face space: colour the visemes' regions by it.
        if (document.visemes && document.visemes->neutral.hasUVs())
            document.visemeColours =
                std::make_shared<const std::vector<Vec3>>(face::faceColours(document.visemes->neutral.uvs));
    }
    validateDocument(document);
    loaded.reduction = project.reduction.result;
    loaded.selectedViseme = project.editor.selectedViseme;
    return loaded;
}

Project projectFromDocument(const Document& document, const std::optional<ReductionResult>& reduction,
                            const std::string& selectedViseme) {
    Project project;
    if (document.avatar.isSet()) {
        project.avatar = {document.avatar.file, document.avatar.pattern, document.avatar.scan->addedRest};
        std::vector<std::vector<Vec3>> sculpted = sculptedAvatarVisemes(document);
        const std::vector<std::string> names = visemeNames(document);
        for (std::size_t i = 0; i < names.size(); ++i)
            project.visemes.push_back(
                {names[i], {}, i < sculpted.size() ? std::move(sculpted[i]) : std::vector<Vec3>{}});
    } else if (const VisemeSet* set = document.visemes.get()) {
        project.neutral.file = document.neutralFile;
        if (document.neutralFile.empty()) project.neutral.embedded = set->neutral;
        for (std::size_t i = 0; i < set->size(); ++i) {
            ProjectViseme viseme{set->visemes[i].name, document.visemeFiles.at(i), {}};
            if (viseme.file.empty()) viseme.positions = set->visemes[i].positions;
            project.visemes.push_back(std::move(viseme));
        }
    }
    project.frequencies = document.frequencies;
    project.weights.mode = document.weights.mode;
    project.weights.painted = document.weights.paintedOrEmpty();
    project.refinement = document.refinement;
    project.reduction.target = document.target;
    project.reduction.constraints = document.constraints;
    project.reduction.rest = document.rest;
    project.reduction.restViseme = document.restViseme;
    project.speech = document.speech;
    project.reduction.result = reduction;
    if (const FaceModel& face = document.face; face.cascade) {
        project.deformation.cascade = *face.cascade;
        project.deformation.values = face.parameters;
        project.deformation.visemes = face.presets.empty() ? oculusVisemes() : face.presets;
        if (face.domain) project.deformation.domain = storedFaceDomain(*face.domain);
    }
    project.editor.selectedViseme = selectedViseme;
    return project;
}

} // namespace vl
