#include "core/gltf/AvatarReport.h"

#include "core/gltf/TargetNames.h"

#include <algorithm>

namespace vl {
namespace {

const char* modeName(int mode) {
    static const char* names[] = {"points",    "lines",          "line loop",   "line strip",
                                  "triangles", "triangle strip", "triangle fan"};
    return mode >= 0 && mode <= 6 ? names[mode] : "unknown mode";
}

std::string withCommas(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

std::string joined(const std::vector<std::string>& items, const char* separator = ", ") {
    std::string out;
    for (const auto& item : items) out += (out.empty() ? "" : separator) + item;
    return out;
}

// What a file VisemeLab reduced says about itself: each key with its members, the resting visemes,
// and what of its extras was ignored.
std::string ownOutputReport(const OwnOutput& own) {
    std::string out;
    if (own.recognised) {
        out += describeOwnOutput(own) + "\n";
        for (const OwnKey& key : own.keys)
            out += "  key " + key.name + ": " + joined(key.members, " ") + "\n";
        if (!own.resting.empty()) out += "  resting (the neutral face): " + joined(own.resting, " ") + "\n";
    }
    for (const std::string& note : own.notes) out += "  extras.visemelab: " + note + "\n";
    return out;
}

nlohmann::ordered_json ownOutputJson(const OwnOutput& own) {
    nlohmann::ordered_json keys = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < own.keys.size(); ++k) {
        nlohmann::ordered_json targets = nlohmann::ordered_json::array();
        for (const OwnMesh& mesh : own.meshes)
            if (!mesh.keyTargets[k].empty())
                targets.push_back({{"mesh", mesh.mesh}, {"target", mesh.keyTargets[k].front()}});
        keys.push_back({{"name", own.keys[k].name},
                        {"members", own.keys[k].members},
                        {"frequency", own.keys[k].frequency},
                        {"targets", targets}});
    }
    nlohmann::ordered_json meshes = nlohmann::ordered_json::array();
    for (const OwnMesh& mesh : own.meshes) {
        nlohmann::ordered_json aliases = nlohmann::ordered_json::object();
        for (const auto& [name, target] : mesh.aliases) aliases[name] = target;
        meshes.push_back({{"mesh", mesh.mesh}, {"aliases", aliases}});
    }
    return {{"recognised", own.recognised},
            {"version", own.version},
            {"names", own.mergedNames ? "merged" : "original"},
            {"keys", keys},
            {"meshes", meshes},
            {"visemes", own.visemeCount()},
            {"resting", own.resting},
            {"notes", own.notes}};
}

} // namespace

std::vector<std::string> suggestedPatterns(const AvatarScan& scan) {
    // VRoid / VRM mouth shapes; Character Creator 4 visemes; the Oculus names without any prefix.
    const std::vector<std::string> known{"Fcl_MTH_[AIUEO]", "V_*", "viseme_*"};
    std::vector<std::string> out;
    for (const std::string& pattern : known)
        for (const AvatarMesh& mesh : scan.meshes) {
            bool found = false;
            for (const AvatarTarget& t : mesh.targets)
                found = found || (t.named && globMatch(pattern, t.name));
            if (found) {
                out.push_back(pattern);
                break;
            }
        }
    return out;
}

std::string formatAvatarMeshReport(const AvatarMesh& m) {
    std::string out;
    out += "mesh " + std::to_string(m.index) + " \"" + m.name + "\"";
    if (m.node >= 0) out += " at node " + std::to_string(m.node);
    if (m.skin >= 0) out += ", skinned (skin " + std::to_string(m.skin) + ")";
    out += ": " + std::to_string(m.primitives.size()) + " primitive" + (m.primitives.size() == 1 ? "" : "s") +
           ", " + std::to_string(m.targets.size()) + " morph targets";
    if (!m.note.empty()) out += " (" + m.note + ")";
    out += "\n";
    for (std::size_t p = 0; p < m.primitives.size(); ++p) {
        const AvatarPrimitive& prim = m.primitives[p];
        out += "  primitive " + std::to_string(p) + ": " + modeName(prim.mode) + ", " +
               withCommas(prim.vertices) + " vertices";
        if (m.carriesVisemes) out += ", " + withCommas(prim.triangles) + " triangles";
        if (!prim.storage.empty()) out += " [" + joined(prim.storage) + "]";
        out += "\n";
    }
    std::vector<std::string> visemes;
    std::vector<std::pair<std::string, std::vector<std::string>>> ignored; // by reason, in order met
    for (const AvatarTarget& t : m.targets) {
        if (t.viseme >= 0) {
            visemes.push_back(t.name);
            continue;
        }
        auto it =
            std::find_if(ignored.begin(), ignored.end(), [&](const auto& r) { return r.first == t.ignored; });
        if (it == ignored.end()) it = ignored.insert(ignored.end(), {t.ignored, {}});
        it->second.push_back(t.name);
    }
    if (!visemes.empty()) out += "  visemes: " + joined(visemes, " ") + "\n";
    if (m.carriesVisemes || visemes.empty())
        for (const auto& [reason, names] : ignored)
            if (m.carriesVisemes || reason.rfind("same", 0) == 0)
                out += "  kept as they are (" + reason + "): " + joined(names, " ") + "\n";
    return out;
}

std::string formatAvatarReport(const AvatarScan& scan) {
    std::size_t primitives = 0;
    for (const AvatarMesh& m : scan.meshes) primitives += m.primitives.size();
    std::string out = scan.source + ": " + std::to_string(scan.meshes.size()) + " meshes, " +
                      std::to_string(primitives) + " primitives, " + withCommas(scan.fileVertices) +
                      " vertices\n";
    if (!scan.extensionsUsed.empty()) out += "  extensions used: " + joined(scan.extensionsUsed) + "\n";
    if (!scan.extensionsRequired.empty())
        out += "  extensions required: " + joined(scan.extensionsRequired) + "\n";
    std::vector<std::string> carriers;
    for (const AvatarMesh& m : scan.meshes)
        if (m.carriesVisemes) carriers.push_back(m.name.empty() ? "mesh " + std::to_string(m.index) : m.name);
    out += "Visemes: " + std::to_string(scan.visemes.size()) + " (" + scan.selection + ")\n";
    if (!scan.visemes.empty()) {
        out += "  " + joined(scan.visemes, " ") + "\n";
        out += "  one set over " + std::to_string(carriers.size()) +
               (carriers.size() == 1 ? " mesh (" : " meshes (") + joined(carriers) +
               "): " + withCommas(scan.set.vertexCount()) + " vertices, " +
               withCommas(scan.set.neutral.triangles.size()) + " triangles, measured in world space\n";
        if (!scan.oculusNames) out += "  (not Oculus viseme names: frequencies default to uniform)\n";
    } else {
        const auto patterns = suggestedPatterns(scan);
        out += "  none found";
        if (!patterns.empty()) out += "; targets match --targets '" + joined(patterns, "' or '") + "'";
        out += "\n";
    }
    out += ownOutputReport(scan.own);
    for (const AvatarMesh& m : scan.meshes) out += formatAvatarMeshReport(m);
    return out;
}

nlohmann::ordered_json avatarReportJson(const AvatarScan& scan) {
    nlohmann::ordered_json j;
    j["file"] = scan.source;
    j["selection"] = scan.selection;
    j["visemes"] = scan.visemes;
    j["oculus_names"] = scan.oculusNames;
    j["vertices"] = scan.fileVertices;
    j["viseme_vertices"] = scan.set.vertexCount();
    j["viseme_triangles"] = scan.set.neutral.triangles.size();
    j["extensions_used"] = scan.extensionsUsed;
    j["extensions_required"] = scan.extensionsRequired;
    if (scan.own.recognised || !scan.own.notes.empty()) j["visemelab"] = ownOutputJson(scan.own);
    nlohmann::ordered_json meshes = nlohmann::ordered_json::array();
    for (const AvatarMesh& m : scan.meshes) {
        nlohmann::ordered_json mesh{{"index", m.index}, {"name", m.name},
                                    {"node", m.node},   {"instances", m.uses},
                                    {"skin", m.skin},   {"carries_visemes", m.carriesVisemes}};
        if (!m.note.empty()) mesh["note"] = m.note;
        nlohmann::ordered_json prims = nlohmann::ordered_json::array();
        for (const AvatarPrimitive& p : m.primitives)
            prims.push_back({{"mode", modeName(p.mode)},
                             {"vertices", p.vertices},
                             {"triangles", p.triangles},
                             {"storage", p.storage}});
        mesh["primitives"] = prims;
        nlohmann::ordered_json visemes = nlohmann::ordered_json::array(),
                               ignored = nlohmann::ordered_json::array();
        for (std::size_t k = 0; k < m.targets.size(); ++k) {
            const AvatarTarget& t = m.targets[k];
            if (t.viseme >= 0)
                visemes.push_back({{"target", k},
                                   {"name", t.name},
                                   {"viseme", scan.visemes[static_cast<std::size_t>(t.viseme)]}});
            else
                ignored.push_back({{"target", k}, {"name", t.name}, {"why", t.ignored}});
        }
        mesh["visemes"] = visemes;
        mesh["ignored"] = ignored;
        meshes.push_back(mesh);
    }
    j["meshes"] = meshes;
    return j;
}

} // namespace vl
