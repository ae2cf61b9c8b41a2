#pragma once
// With merged names the viseme targets of a mesh collapse into its keys, so every place that
// addresses a mesh's morph targets by index follows: mesh.weights and node.weights (a key's default
// weight is the sum of its members'), animation channels of path "weights" (a new output accessor
// per rewritten sampler, each keyframe's key weight the sum of its members'; a sampler shared by
// meshes that move differently is duplicated), VRM 0.x blendShapeMaster binds {mesh, index} and
// VRM 1.0 expression morphTargetBinds {node, index} (binds that now hit the same target merge,
// keeping the larger weight).
#include <map>
#include <vector>

namespace vl {

class GlbRepack;
class AccessorReader;

// `remaps`: mesh index -> (old target index -> new target index).
void remapMorphTargets(GlbRepack& out, AccessorReader& reader, const std::map<int, std::vector<int>>& remaps);

} // namespace vl
