#include "core/project/LandmarksJson.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/io/JsonWrite.h"

namespace vl {

std::vector<std::pair<face::Landmark, face::LandmarkInput>> landmarksFromJsonText(std::string_view text,
                                                                                  std::string_view source) {
    const Json document = parseJsonStrict(text, source);
    const JsonNode root(document, std::string(source) + ":");
    root.expectObject();
    root.allowOnly({"format", "landmarks"});
    if (root.has("format") && root["format"].string() != "visemelab-landmarks")
        root["format"].fail("expected \"visemelab-landmarks\"");
    std::vector<std::pair<face::Landmark, face::LandmarkInput>> result;
    for (const auto& [name, node] : root["landmarks"].members()) {
        const auto landmark = fromString<face::Landmark>(name);
        if (!landmark)
            node.fail("unknown landmark \"" + name + "\" (known: " + enumNameList<face::Landmark>(", ") +
                      ")");
        node.expectObject();
        node.allowOnly({"vertex", "uv", "position", "source", "confidence", "method"});
        face::LandmarkInput input;
        if (node.has("vertex")) {
            input.kind = face::LandmarkInput::Kind::Vertex;
            input.vertex = static_cast<std::uint32_t>(node["vertex"].integerInRange(0, 0xFFFFFFFEll));
        } else if (node.has("uv")) {
            input.kind = face::LandmarkInput::Kind::UV;
            input.uv = node["uv"].vec2();
        } else if (node.has("position")) {
            input.kind = face::LandmarkInput::Kind::Position;
            input.position = node["position"].vec3();
        } else {
            node.fail("give \"vertex\", \"uv\" or \"position\"");
        }
        result.emplace_back(*landmark, input);
    }
    return result;
}

std::vector<std::pair<face::Landmark, face::LandmarkInput>>
readLandmarkFile(const std::filesystem::path& file) {
    return landmarksFromJsonText(readFileToString(file), file.string());
}

std::string landmarksToJsonText(const face::FaceLandmarks& landmarks) {
    Json list = Json::object();
    for (const auto l : face::allLandmarks()) {
        const auto& found = landmarks[l];
        if (!found.found()) continue;
        Json entry = Json::object();
        entry["uv"] = Json::array({found.uv[0], found.uv[1]});
        entry["position"] = Json::array({found.position[0], found.position[1], found.position[2]});
        entry["source"] = face::sourceName(found.source);
        entry["confidence"] = found.confidence;
        entry["method"] = found.method;
        list[std::string(toString(l))] = std::move(entry);
    }
    Json root = Json::object();
    root["format"] = "visemelab-landmarks";
    root["landmarks"] = std::move(list);
    return formatJsonPretty(root);
}

} // namespace vl
