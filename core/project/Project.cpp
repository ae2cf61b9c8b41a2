#include "core/project/Project.h"
#include "core/project/ProjectCompare.h"

namespace vl {

bool sameMesh(const MeshData& a, const MeshData& b) {
    return a.positions == b.positions && a.uvs == b.uvs && a.triangles == b.triangles;
}

bool sameFrequencies(const FrequencySource& a, const FrequencySource& b) {
    return a.visemeFrequencies.entries == b.visemeFrequencies.entries &&
           a.phonemes.entries == b.phonemes.entries && a.map.entries == b.map.entries;
}

bool sameField(const VectorField& a, const VectorField& b) {
    if (a.sampled.width != b.sampled.width || a.sampled.height != b.sampled.height ||
        a.sampled.samples != b.sampled.samples || a.influences.size() != b.influences.size())
        return false;
    for (std::size_t k = 0; k < a.influences.size(); ++k) {
        const auto& x = a.influences[k];
        const auto& y = b.influences[k];
        if (x.centre != y.centre || x.radii != y.radii || x.plateau != y.plateau ||
            x.rotation != y.rotation || x.direction != y.direction || x.magnitude != y.magnitude ||
            x.falloff != y.falloff)
            return false;
    }
    return true;
}

bool sameDeformation(const ProjectDeformation& a, const ProjectDeformation& b) {
    const auto& x = a.cascade;
    const auto& y = b.cascade;
    if (x.name != y.name || x.parameters.size() != y.parameters.size() ||
        x.stages.size() != y.stages.size() || a.values != b.values || a.visemes.size() != b.visemes.size())
        return false;
    for (std::size_t k = 0; k < x.parameters.size(); ++k) {
        const auto& p = x.parameters[k];
        const auto& q = y.parameters[k];
        if (p.name != q.name || p.min != q.min || p.max != q.max || p.defaultValue != q.defaultValue)
            return false;
    }
    for (std::size_t k = 0; k < x.stages.size(); ++k) {
        const auto& s = x.stages[k];
        const auto& t = y.stages[k];
        if (s.kind != t.kind || s.name != t.name ||
            (s.kind == StageKind::AddVector && s.parameter != t.parameter) || !sameField(s.field, t.field))
            return false;
    }
    for (std::size_t k = 0; k < a.visemes.size(); ++k)
        if (a.visemes[k].name != b.visemes[k].name || a.visemes[k].values != b.visemes[k].values)
            return false;
    return true;
}

bool sameRefinement(const CriterionSettings& a, const CriterionSettings& b) {
    return a.kind == b.kind && a.maxDepth == b.maxDepth && a.depth.depth == b.depth.depth &&
           a.normals.dihedralAngleDeg == b.normals.dihedralAngleDeg &&
           a.normals.normalAngleDeg == b.normals.normalAngleDeg &&
           a.contour.averageError == b.contour.averageError &&
           a.contour.maximumError == b.contour.maximumError &&
           a.contour.samplesPerSide == b.contour.samplesPerSide;
}

bool sameResult(const std::optional<ReductionResult>& a, const std::optional<ReductionResult>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    if (a->curve.size() != b->curve.size()) return false;
    for (std::size_t p = 0; p < a->curve.size(); ++p)
        if (a->curve[p].cost != b->curve[p].cost || a->curve[p].groups != b->curve[p].groups ||
            a->curve[p].optimal != b->curve[p].optimal || a->curve[p].lowerBound != b->curve[p].lowerBound)
            return false;
    return true;
}

int Project::findViseme(std::string_view name) const {
    for (std::size_t i = 0; i < visemes.size(); ++i)
        if (visemes[i].name == name) return static_cast<int>(i);
    return -1;
}

bool operator==(const Project& a, const Project& b) {
    if (a.visemes.size() != b.visemes.size()) return false;
    for (std::size_t i = 0; i < a.visemes.size(); ++i) {
        const auto& x = a.visemes[i];
        const auto& y = b.visemes[i];
        if (x.name != y.name || x.file != y.file || x.positions != y.positions) return false;
    }
    return a.path == b.path && a.neutral.file == b.neutral.file &&
           sameMesh(a.neutral.embedded, b.neutral.embedded) &&
           sameFrequencies(a.frequencies, b.frequencies) && a.weights.mode == b.weights.mode &&
           a.weights.painted == b.weights.painted && sameDeformation(a.deformation, b.deformation) &&
           sameRefinement(a.refinement, b.refinement) && a.reduction.target == b.reduction.target &&
           a.reduction.constraints == b.reduction.constraints &&
           sameResult(a.reduction.result, b.reduction.result) &&
           a.editor.selectedViseme == b.editor.selectedViseme;
}

} // namespace vl
