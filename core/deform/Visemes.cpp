#include "core/deform/Visemes.h"

#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/deform/CascadeSampler.h"

#include <set>

namespace vl {

std::vector<VisemeParameters> oculusVisemes() {
    // Mouth shapes after the Oculus/Meta viseme reference; values are fractions of each muscle's range.
    return {
        {"sil", {}},
        // Lips pressed shut: lip_press alone (a pucker, even a slight one, parts the lip middles), at the
        // ARPAbet M's 0.8: a harder press pushes the lips onto the lower teeth (docs/viseme-review.md).
        {"PP", {{"lip_press", 0.8}}},
        {"FF",
         {{"lower_lip_tuck", 1.0},
          {"upper_lip_raise", 0.35},
          {"jaw_open", 0.08},
          {"risorius_l", 0.2},
          {"risorius_r", 0.2}}},
        {"TH",
         {{"jaw_open", 0.25},
          {"upper_lip_raise", 0.2},
          {"risorius_l", 0.15},
          {"risorius_r", 0.15},
          {"tongue_out", 1.0}}},
        {"DD",
         {{"jaw_open", 0.2},
          {"risorius_l", 0.3},
          {"risorius_r", 0.3},
          {"upper_lip_raise", 0.15},
          {"tongue_up", 0.8}}},
        {"kk", {{"jaw_open", 0.4}, {"risorius_l", 0.35}, {"risorius_r", 0.35}}},
        {"CH", {{"lip_pucker", 0.6}, {"jaw_open", 0.22}, {"upper_lip_raise", 0.45}}},
        {"SS",
         {{"jaw_open", 0.1},
          {"risorius_l", 0.6},
          {"risorius_r", 0.6},
          {"zygomatic_l", 0.2},
          {"zygomatic_r", 0.2},
          {"upper_lip_raise", 0.3}}},
        {"nn", {{"jaw_open", 0.22}, {"risorius_l", 0.25}, {"risorius_r", 0.25}, {"tongue_up", 1.0}}},
        {"RR", {{"lip_pucker", 0.45}, {"jaw_open", 0.25}}},
        {"aa", {{"jaw_open", 1.0}, {"frontalis_l", 0.2}, {"frontalis_r", 0.2}}},
        {"E",
         {{"jaw_open", 0.45},
          {"risorius_l", 0.55},
          {"risorius_r", 0.55},
          {"zygomatic_l", 0.3},
          {"zygomatic_r", 0.3}}},
        {"ih",
         {{"jaw_open", 0.3},
          {"risorius_l", 0.75},
          {"risorius_r", 0.75},
          {"zygomatic_l", 0.15},
          {"zygomatic_r", 0.15}}},
        {"oh", {{"jaw_open", 0.65}, {"lip_pucker", 0.55}}},
        {"ou", {{"lip_pucker", 1.0}, {"jaw_open", 0.2}}},
    };
}

std::vector<double> parameterVector(const DeformationCascade& cascade, const VisemeParameters& viseme) {
    std::vector<double> q = cascade.defaults();
    std::set<std::string, std::less<>> seen;
    const std::string where = "viseme '" + viseme.name + "'";
    for (const auto& [name, value] : viseme.values) {
        const int k = cascade.findParameter(name);
        if (k < 0) throwInputError(where, "unknown parameter '" + name + "'");
        if (!seen.insert(name).second) throwInputError(where, "parameter '" + name + "' is given twice");
        const auto& p = cascade.parameters[static_cast<std::size_t>(k)];
        if (!(value >= p.min && value <= p.max))
            throwInputError(where, "parameter '" + name + "': value " + formatDouble(value) +
                                       " is outside [" + formatDouble(p.min) + ", " + formatDouble(p.max) +
                                       "]");
        q[static_cast<std::size_t>(k)] = value;
    }
    return q;
}

VisemeSet generateVisemeSet(const DeformationCascade& cascade, const MeshData& uvMesh,
                            std::span<const VisemeParameters> visemes) {
    if (!uvMesh.hasUVs() || uvMesh.uvs.size() != uvMesh.positions.size())
        throwInputError("viseme generation", "the mesh needs one (u,v) per vertex");
    if (visemes.size() < 2)
        throwInputError("viseme generation",
                        "needs at least 2 visemes, got " + std::to_string(visemes.size()));
    std::set<std::string, std::less<>> names;
    for (const auto& v : visemes) {
        if (v.name.empty()) throwInputError("viseme generation", "a viseme has an empty name");
        if (!names.insert(v.name).second)
            throwInputError("viseme generation", "viseme '" + v.name + "' repeats");
    }
    const CascadeSampler sampler(cascade, uvMesh.uvs);
    VisemeSet set;
    set.neutral.uvs = uvMesh.uvs;
    set.neutral.triangles = uvMesh.triangles;
    set.neutral.positions = sampler.evaluate(cascade.defaults());
    for (const auto& v : visemes) {
        Viseme out;
        out.name = v.name;
        out.positions = sampler.evaluate(parameterVector(cascade, v));
        set.visemes.push_back(std::move(out));
    }
    return set;
}

} // namespace vl
