// The optional "avatar" object of a project: the avatar file the meshes come from and the pattern
// selecting its viseme targets. Written only by projects that have one.
#include "core/common/Error.h"
#include "core/gltf/TargetNames.h"
#include "core/project/ProjectJson.h"

namespace vl {

Json avatarToJson(const ProjectAvatar& avatar) {
    Json json = Json::object();
    json["file"] = avatar.file.generic_string();
    if (!avatar.targets.empty()) json["targets"] = avatar.targets;
    return json;
}

ProjectAvatar avatarFromJson(const JsonNode& node, const ProjectReadContext& context) {
    node.expectObject();
    node.allowOnly({"file", "targets"});
    ProjectAvatar avatar;
    avatar.file = fileFromJson(node["file"], context);
    if (node.has("targets")) {
        const JsonNode targets = node["targets"];
        avatar.targets = targets.nonEmptyString();
        try {
            checkGlobPattern(avatar.targets, "pattern");
        } catch (const InputError& e) {
            targets.fail(e.what());
        }
    }
    return avatar;
}

} // namespace vl
