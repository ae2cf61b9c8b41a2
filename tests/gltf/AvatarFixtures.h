#pragma once
// Avatar files the project makes itself, shaped like what real tools export (nothing here is copied
// from a real avatar):
// - rpmLikeAvatar: Ready Player Me-like. Skinned Wolf3D_Head and Wolf3D_Teeth, EyeLeft/EyeRight
//   placed by node matrices under the Head joint of an Armature scaled 0.01 (as FBX conversions
//   write it), a Wolf3D_Body without targets; the head carries ARKit targets around the 15 viseme_*
//   targets, teeth and eyes carry the visemes too; a textured material with KHR_texture_transform,
//   KHR_materials_emissive_strength, an animation of a joint and of the head's morph weights,
//   extras on nodes, meshes and the asset. Storage variants: plain floats, KHR_mesh_quantization
//   (unskinned: the dequantisation sits in node transforms), EXT_meshopt_compression (meshoptimizer's
//   encoder, exponential and octahedral filters, a fallback buffer without data), sparse targets,
//   KHR_draco_mesh_compression (head primitive, Draco's encoder; targets follow the decoded order).
// - vroidLikeAvatar: VRoid Studio-like. "Face" with two primitives and Fcl_ALL_* / Fcl_EYE_* /
//   Fcl_MTH_* targets named in the primitives' extras (as UniVRM writes them), a Body, and the VRM
//   0.x "VRM" extension (or VRM 1.0 "VRMC_vrm") whose expressions bind morph targets by index.
#include <string>
#include <vector>

namespace vl::test {

enum class FixtureStorage { Plain, Quantised, Meshopt, Sparse, Draco };

struct AvatarFixtureOptions {
    FixtureStorage storage = FixtureStorage::Plain;
    int headColumns = 24, headRows = 14; // head grid: columns x rows vertices
    int teethColumns = 12, teethRows = 3;
    int eyeSegments = 8; // eye spheres: segments x segments/2 vertices
    bool animation = true;
    bool restTarget = true;   // false: no viseme_sil target on any mesh (an avatar without a rest viseme)
    bool byteWeights = false; // the weights animation as normalised unsigned bytes (as gltfpack stores it)
};

std::string rpmLikeAvatar(const AvatarFixtureOptions& options = {});
std::string vroidLikeAvatar(bool vrm1 = false);

// The names the fixtures give their targets.
std::vector<std::string> rpmVisemeNames();       // viseme_sil ... viseme_U (RPM spelling)
std::vector<std::string> rpmHeadTargetNames();   // the head's full list, in file order
std::vector<std::string> vroidFaceTargetNames(); // Fcl_*

} // namespace vl::test
