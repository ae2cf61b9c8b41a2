#include "core/project/FaceProject.h"

#include "core/common/Error.h"

#include <algorithm>

namespace vl {

Project makeFaceProject(const DeformationCascade& cascade, const MeshData& domain,
                        const std::vector<VisemeParameters>& visemes, double lengthScale) {
    Project project;
    project.deformation.cascade = cascade;
    project.deformation.values = cascade.defaults();
    project.deformation.visemes = visemes;
    for (const auto& v : visemes) {
        project.visemes.push_back({v.name, {}, {}});
        project.frequencies.visemeFrequencies.entries.emplace_back(v.name, 1.0);
    }
    project.reduction.target = std::max(1, static_cast<int>(visemes.size()) * 2 / 3);
    project.refinement.contour.averageError *= lengthScale;
    project.refinement.contour.maximumError *= lengthScale;
    regenerateFaceVisemes(project, domain);
    return project;
}

void regenerateFaceVisemes(Project& project, const MeshData& domain) {
    if (!project.deformation.isSet())
        throwInputError("project", "has no deformable face to generate visemes from");
    std::vector<VisemeParameters> visemes;
    for (const auto& v : project.visemes) {
        const auto it = std::find_if(project.deformation.visemes.begin(), project.deformation.visemes.end(),
                                     [&](const VisemeParameters& p) { return p.name == v.name; });
        if (it == project.deformation.visemes.end())
            throwInputError("/visemes",
                            "viseme \"" + v.name + "\" has no parameter vector in /deformation/visemes");
        visemes.push_back(*it);
    }
    const VisemeSet set = generateVisemeSet(project.deformation.cascade, domain, visemes);
    project.neutral = {};
    project.neutral.embedded = set.neutral;
    for (std::size_t k = 0; k < set.size(); ++k) {
        project.visemes[k].file.clear();
        project.visemes[k].positions = set.visemes[k].positions;
    }
    project.deformation.domain = projectDomainMesh(domain);
    project.reduction.result.reset(); // computed for other meshes
}

MeshData projectDomainMesh(const MeshData& mesh) {
    MeshData domain;
    domain.uvs = mesh.uvs;
    domain.triangles = mesh.triangles;
    domain.positions.reserve(mesh.uvs.size());
    for (const Vec2& uv : mesh.uvs) domain.positions.emplace_back(uv[0], uv[1], 0.0);
    return domain;
}

} // namespace vl
