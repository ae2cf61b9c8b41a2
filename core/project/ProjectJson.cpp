// The project document of the current version: top level, meshes, weights and editor state.
#include "core/project/ProjectJson.h"

#include "core/common/Error.h"

#include <set>
#include <system_error>
#include <unordered_set>

namespace vl {

namespace {

Json vec3Array(const std::vector<Vec3>& points) {
    Json array = Json::array();
    for (const Vec3& p : points) array.push_back(Json::array({p[0], p[1], p[2]}));
    return array;
}

std::vector<Vec3> vec3ArrayFromJson(const JsonNode& node) {
    if (node.size() == 0) node.fail("expected at least one vertex");
    std::vector<Vec3> points;
    points.reserve(node.size());
    for (const JsonNode& e : node.elements()) points.push_back(e.vec3());
    return points;
}

void checkFile(const JsonNode& node, const std::filesystem::path& file, const ProjectReadContext& context) {
    if (!context.checkFiles) return;
    const auto resolved = file.is_absolute() ? file : context.folder / file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(resolved, ec))
        node.fail("file not found (" + resolved.string() + ")");
}

Json neutralToJson(const ProjectNeutral& neutral) {
    if (!neutral.file.empty() && !neutral.embedded.positions.empty())
        throwInputError("/neutral", "has both a file and embedded data; clear one of them");
    if (!neutral.file.empty()) return Json{{"file", neutral.file.generic_string()}};
    if (neutral.embedded.positions.empty()) return nullptr;
    Json json = Json::object();
    json["positions"] = vec3Array(neutral.embedded.positions);
    if (neutral.embedded.hasUVs()) json["uvs"] = uvArrayToJson(neutral.embedded.uvs);
    json["triangles"] = trianglesToJson(neutral.embedded.triangles);
    return json;
}

MeshData embeddedMeshFromJson(const JsonNode& node) {
    MeshData mesh;
    mesh.positions = vec3ArrayFromJson(node["positions"]);
    if (node.has("uvs")) {
        const auto n = mesh.positions.size();
        const JsonNode uvs = node["uvs"];
        if (uvs.size() != mesh.positions.size())
            uvs.fail("expected " + std::to_string(n) + " (u,v) pairs, one per vertex, found " +
                     std::to_string(uvs.size()));
        for (const JsonNode& uv : uvs.elements()) mesh.uvs.push_back(uv.vec2());
    }
    mesh.triangles = trianglesFromJson(node["triangles"], mesh.positions.size());
    return mesh;
}

ProjectNeutral neutralFromJson(const JsonNode& node, const ProjectReadContext& context) {
    ProjectNeutral neutral;
    if (node.isNull()) return neutral;
    node.expectObject();
    if (node.has("file")) {
        node.allowOnly({"file"});
        neutral.file = fileFromJson(node["file"], context);
    } else {
        node.allowOnly({"positions", "uvs", "triangles"});
        neutral.embedded = embeddedMeshFromJson(node);
    }
    return neutral;
}

Json visemeToJson(const ProjectViseme& viseme, std::size_t index) {
    if (!viseme.file.empty() && !viseme.positions.empty())
        throwInputError(jsonPathAppend("/visemes", index),
                        "has both a file and embedded positions; clear one of them");
    Json json = Json::object();
    json["name"] = viseme.name;
    if (!viseme.file.empty())
        json["file"] = viseme.file.generic_string();
    else
        json["positions"] = vec3Array(viseme.positions);
    return json;
}

ProjectViseme visemeFromJson(const JsonNode& node, const ProjectNeutral& neutral,
                             const ProjectReadContext& context) {
    node.allowOnly({"name", "file", "positions"});
    ProjectViseme viseme;
    viseme.name = node["name"].nonEmptyString();
    if (node.has("file") && node.has("positions"))
        node.fail("give either \"file\" or \"positions\", not both");
    if (!node.has("positions")) {
        viseme.file = fileFromJson(node["file"], context); // reports "missing field" when neither is given
        return viseme;
    }
    const JsonNode positions = node["positions"];
    viseme.positions = vec3ArrayFromJson(positions);
    // With a neutral from a file the count is checked when the meshes are loaded.
    if (neutral.isEmbedded() && viseme.positions.size() != neutral.embedded.positions.size())
        positions.fail("expected " + std::to_string(neutral.embedded.positions.size()) +
                       " vertices (as the neutral mesh), found " + std::to_string(viseme.positions.size()));
    return viseme;
}

Json weightsToJson(const ProjectWeights& weights) {
    Json json = Json::object();
    json["mode"] = toString(weights.mode);
    if (!weights.painted.empty()) json["painted"] = weights.painted;
    return json;
}

ProjectWeights weightsFromJson(const JsonNode& node, const ProjectNeutral& neutral) {
    node.allowOnly({"mode", "painted"});
    ProjectWeights weights;
    const JsonNode mode = node["mode"];
    const auto parsed = fromString<WeightMode>(mode.string());
    if (!parsed)
        mode.fail("unknown weight mode \"" + mode.string() + "\" (expected " + enumNameList<WeightMode>() +
                  ")");
    weights.mode = *parsed;
    if (weights.mode == WeightMode::Painted || node.has("painted")) {
        const JsonNode painted = node["painted"];
        weights.painted = painted.nonNegativeNumbers();
        if (neutral.isEmbedded() && weights.painted.size() != neutral.embedded.positions.size())
            painted.fail("expected " + std::to_string(neutral.embedded.positions.size()) +
                         " weights (one per vertex), found " + std::to_string(weights.painted.size()));
        bool anyPositive = false;
        for (const double w : weights.painted) anyPositive = anyPositive || w > 0.0;
        if (!anyPositive) painted.fail("all weights are zero");
    }
    return weights;
}

} // namespace

Json uvArrayToJson(const std::vector<Vec2>& uvs) {
    Json array = Json::array();
    for (const Vec2& uv : uvs) array.push_back(Json::array({uv[0], uv[1]}));
    return array;
}

Json trianglesToJson(const std::vector<Triangle>& triangles) {
    Json array = Json::array();
    for (const Triangle& t : triangles) array.push_back(Json::array({t[0], t[1], t[2]}));
    return array;
}

std::vector<Triangle> trianglesFromJson(const JsonNode& node, std::size_t vertexCount) {
    if (node.size() == 0) node.fail("expected at least one triangle");
    const auto last = static_cast<std::int64_t>(vertexCount) - 1;
    std::vector<Triangle> triangles;
    triangles.reserve(node.size());
    for (const JsonNode& t : node.elements()) {
        t.expectSize(3);
        Triangle triangle{};
        for (std::size_t c = 0; c < 3; ++c)
            triangle[c] = static_cast<std::uint32_t>(t[c].integerInRange(0, last));
        if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2])
            t.fail("a triangle repeats a vertex index");
        triangles.push_back(triangle);
    }
    return triangles;
}

std::filesystem::path fileFromJson(const JsonNode& node, const ProjectReadContext& context) {
    const std::filesystem::path file(node.nonEmptyString());
    checkFile(node, file, context);
    return file;
}

Json projectToJson(const Project& project) {
    std::vector<std::string> names;
    for (const auto& v : project.visemes) names.push_back(v.name);

    Json root = Json::object();
    root["format"] = kProjectFormat;
    root["version"] = projectVersionFor(project);
    root["neutral"] = neutralToJson(project.neutral);
    Json visemes = Json::array();
    for (std::size_t i = 0; i < project.visemes.size(); ++i)
        if (!project.avatar.isSet())
            visemes.push_back(visemeToJson(project.visemes[i], i));
        else if (project.visemes[i].positions.empty())
            visemes.push_back(Json{{"name", project.visemes[i].name}});
        else // sculpted in the editor: its world-space positions over the avatar's meshes
            visemes.push_back(Json{{"name", project.visemes[i].name},
                                   {"positions", vec3Array(project.visemes[i].positions)}});
    root["visemes"] = std::move(visemes);
    root["frequencies"] = frequenciesToJson(project.frequencies);
    root["weights"] = weightsToJson(project.weights);
    root["deformation"] = deformationToJson(project.deformation);
    root["refinement"] = refinementToJson(project.refinement);
    root["reduction"] = reductionToJson(project.reduction, names);
    if (!project.speech.isDefault()) root["speech"] = speechToJson(project.speech);
    root["editor"] = Json{{"selectedViseme", project.editor.selectedViseme}};
    if (project.avatar.isSet()) root["avatar"] = avatarToJson(project.avatar);
    return root;
}

Project projectFromJson(const JsonNode& root, const ProjectReadContext& context) {
    root.allowOnly({"format", "version", "neutral", "visemes", "frequencies", "weights", "deformation",
                    "refinement", "reduction", "speech", "editor", "avatar"});
    Project project;
    project.neutral = neutralFromJson(root["neutral"], context);
    if (root.has("avatar")) {
        project.avatar = avatarFromJson(root["avatar"], context);
        if (project.neutral.isSet())
            root["neutral"].fail("must be null: the meshes of an avatar project come from /avatar/file");
    }

    const JsonNode visemes = root["visemes"];
    std::vector<std::string> names;
    std::unordered_set<std::string> seen; // linear-time duplicate check, however many visemes
    for (const JsonNode& v : visemes.elements()) {
        if (project.avatar.isSet()) {           // the avatar holds the meshes: a viseme is its name
            v.allowOnly({"name", "positions"}); // positions: sculpted (counts checked with the avatar)
            if (v.has("positions") && context.version < 5)
                v["positions"].fail("a sculpted avatar viseme needs project version 5 (this file says " +
                                    std::to_string(context.version) + ")");
            project.visemes.push_back(
                {v["name"].nonEmptyString(),
                 {},
                 v.has("positions") ? vec3ArrayFromJson(v["positions"]) : std::vector<Vec3>{}});
        } else {
            project.visemes.push_back(visemeFromJson(v, project.neutral, context));
        }
        const std::string& name = project.visemes.back().name;
        if (!seen.insert(name).second) v["name"].fail("duplicate viseme name \"" + name + "\"");
        names.push_back(name);
    }
    if (!names.empty() && !project.neutral.isSet() && !project.avatar.isSet())
        root["neutral"].fail("a neutral mesh is required when visemes are listed");

    if (root.has("frequencies")) project.frequencies = frequenciesFromJson(root["frequencies"], names);
    if (root.has("weights")) project.weights = weightsFromJson(root["weights"], project.neutral);
    if (root.has("deformation")) project.deformation = deformationFromJson(root["deformation"], context);
    if (root.has("refinement")) project.refinement = refinementFromJson(root["refinement"]);
    if (root.has("reduction")) project.reduction = reductionFromJson(root["reduction"], names, context);
    if (root.has("speech")) project.speech = speechFromJson(root["speech"]);
    if (root.has("editor")) {
        const JsonNode editor = root["editor"];
        editor.allowOnly({"selectedViseme"});
        if (editor.has("selectedViseme")) {
            const JsonNode selected = editor["selectedViseme"];
            project.editor.selectedViseme = selected.string();
            if (!project.editor.selectedViseme.empty() &&
                project.findViseme(project.editor.selectedViseme) < 0)
                selected.fail("unknown viseme \"" + project.editor.selectedViseme + "\"");
        }
    }
    return project;
}

} // namespace vl
