#pragma once
// A project made from a deformable face (a user's own, or the bundled one): the cascade, its
// visemes as parameter vectors, and the viseme meshes generated on a (u,v) mesh of the face domain,
// embedded so the project exports at once (`visemelab export`).
#include "core/project/Project.h"

namespace vl {

// `domain` is the (u,v) mesh the visemes are generated on (face::faceDomainMesh, or a refined one);
// `lengthScale` is the face's size in model units per bundled-face centimetre: the contour
// criterion's error thresholds scale with it. Every viseme gets frequency 1 (uniform) until the
// user sets real ones; the reduction target is two thirds of the viseme count.
Project makeFaceProject(const DeformationCascade& cascade, const MeshData& domain,
                        const std::vector<VisemeParameters>& visemes, double lengthScale = 1.0);

// Replaces the project's embedded viseme meshes with ones generated from its deformation on `domain`
// (after refinement) and stores `domain` as the face's (u,v) mesh. Keeps names, order and the rest.
void regenerateFaceVisemes(Project& project, const MeshData& domain);

// A (u,v) mesh as a project stores it (ProjectDeformation::domain): its (u,v) and triangles, with
// positions (u, v, 0).
MeshData projectDomainMesh(const MeshData& mesh);

} // namespace vl
