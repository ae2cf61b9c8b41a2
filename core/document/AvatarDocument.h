#pragma once
// Documents made from an avatar (glTF / GLB / VRM): the editor's File > Import avatar... and
// File > Export avatar..., on the same core as `visemelab avatar reduce` (core/gltf).
//
// The document's viseme set is the avatar's visemes over the concatenated world-space geometry of
// every mesh carrying one (core/gltf/AvatarScan.h): reduction, weights and painting work on it as on
// any set. The avatar itself stays in memory as read (DocumentAvatar), so an export writes the same
// avatar back with its viseme targets replaced by the reduced keys, whatever happened to the file.
#include "core/document/Document.h"
#include "core/gltf/AvatarWriter.h"

#include <filesystem>
#include <string>
#include <vector>

namespace vl {

// Reads and scans an avatar with a target pattern (empty: the Oculus visemes), the meshes without
// visemes included (shown greyed), and the rest viseme `addedRest` added when not empty
// (core/gltf/AvatarRest.h). Throws InputError naming the file and element.
DocumentAvatar loadDocumentAvatar(const std::filesystem::path& file, const std::string& pattern,
                                  const std::string& addedRest = {});

// A new document of the avatar's visemes: frequencies from defaultAvatarFrequencies(scan,
// oculusTable) (the bundled en-us table and Oculus map for Oculus names, else equal), uniform
// weights, m = n / 2. Throws InputError naming the file when it has fewer than 2 visemes (with the
// patterns of known conventions that match some of its targets).
Document documentFromAvatar(DocumentAvatar avatar, const FrequencySource& oculusTable);

// The project of a new avatar document (`visemelab project new --avatar`): the avatar file and target
// pattern, the visemes by name, the frequencies, weights and target documentFromAvatar chooses; with
// `addRest`, an avatar whose visemes lack a rest viseme gains one (edit::addAvatarRestViseme).
// Throws what loadDocumentAvatar and documentFromAvatar throw.
Project newAvatarProject(const std::filesystem::path& file, const std::string& pattern,
                         const FrequencySource& oculusTable, bool addRest = false);

// The document's avatar with its visemes grouped by `groupOf` (viseme i -> key, 0..m-1): keys are
// the frequency-weighted means of their members on every mesh (core/gltf/AvatarWriter.h), written
// as a GLB. Throws InputError when the document has no avatar or writing is refused.
std::string reducedAvatarGlb(const Document& document, const std::vector<int>& groupOf,
                             const AvatarWriteOptions& options = {}, AvatarWriteSummary* summary = nullptr);

// Sculpted avatar visemes (the editor's Sculpt on an avatar): per viseme of the document's set, its
// world-space positions where they differ from the avatar file's, else empty; all empty when nothing
// was sculpted. What the writer maps back into each mesh's space (AvatarWriteOptions::sculpted) and
// what a project stores.
std::vector<std::vector<Vec3>> sculptedAvatarVisemes(const Document& document);

// The document's set becomes the avatar's with `sculpted` (as sculptedAvatarVisemes returns, by
// viseme index) over it. Throws InputError naming `where` and the viseme when a shape has the wrong
// vertex count or moves a vertex no target of that viseme can move (avatarSculptableVertices).
void applyAvatarSculpts(Document& document, const std::vector<std::vector<Vec3>>& sculpted,
                        const std::string& where);

// Per vertex of the avatar's set: whether viseme `viseme` can move it, i.e. its mesh carries a
// target of that viseme (a target is only ever replaced, never added, so the others stay put).
std::vector<char> avatarSculptableVertices(const AvatarScan& scan, std::size_t viseme);

// Refuses (InputError) an output that is the avatar the document was read from, or a .gltf name
// (the reduced avatar is a GLB), or a document without avatar.
void checkAvatarOutput(const Document& document, const std::filesystem::path& out);

} // namespace vl
