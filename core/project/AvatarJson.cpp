// The optional "avatar" object of a project: the avatar file the meshes come from, the pattern
// selecting its viseme targets and the rest viseme added to them (version 4). Written only by
// projects that have one.
#include "core/common/Error.h"
#include "core/gltf/TargetNames.h"
#include "core/project/ProjectJson.h"

#include <algorithm>
#include <iterator>

namespace vl {

Json avatarToJson(const ProjectAvatar& avatar) {
    Json json = Json::object();
    json["file"] = avatar.file.generic_string();
    if (!avatar.targets.empty()) json["targets"] = avatar.targets;
    if (!avatar.addedRest.empty()) json["addedRest"] = avatar.addedRest;
    return json;
}

ProjectAvatar avatarFromJson(const JsonNode& node, const ProjectReadContext& context) {
    node.expectObject();
    node.allowOnly({"file", "targets", "addedRest"});
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
    if (node.has("addedRest")) {
        const JsonNode rest = node["addedRest"];
        if (context.version < 4)
            rest.fail("an added rest viseme needs project version 4 (this file says " +
                      std::to_string(context.version) + ")");
        avatar.addedRest = rest.nonEmptyString();
        if (std::find(std::begin(kRestVisemeNames), std::end(kRestVisemeNames), avatar.addedRest) ==
            std::end(kRestVisemeNames))
            rest.fail("an added rest viseme is named sil or viseme_sil, not '" + avatar.addedRest + "'");
    }
    return avatar;
}

} // namespace vl
