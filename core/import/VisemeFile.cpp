#include "core/import/VisemeFile.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/FileNames.h"
#include "core/common/TextParsing.h"
#include "core/io/JsonRead.h"
#include "core/mesh/VisemeSet.h"

#include <unordered_set>

namespace vl {

std::vector<VisemeParameters> parseVisemeFile(std::string_view text, std::string_view source,
                                              const DeformationCascade& face) {
    const Json document = parseJsonStrict(text, source);
    const JsonNode root(document, std::string(source) + ":");
    if (!document.is_object() || !root.has("visemes"))
        throwInputError(source, "expected an object with a \"visemes\" array");
    std::vector<VisemeParameters> visemes;
    std::unordered_set<std::string> names;
    checkVisemeSetSize(root["visemes"].size(), 0, root["visemes"].path()); // before any viseme is built
    for (const JsonNode& entry : root["visemes"].elements()) {
        entry.expectObject();
        entry.allowOnly({"name", "file", "parameters", "ipa", "example", "note"});
        VisemeParameters v;
        const JsonNode nameNode = entry["name"];
        v.name = nameNode.nonEmptyString();
        // The name becomes <name>.obj in the output folder: nothing that leaves it or hits neutral.obj.
        if (fileSafeName(v.name) != v.name || v.name == "neutral")
            nameNode.fail("viseme name \"" + v.name +
                          "\" cannot be a file name (letters, digits, '-', '_', '+' only; not \"neutral\")");
        if (!names.insert(v.name).second) nameNode.fail("viseme \"" + v.name + "\" is listed twice");
        if (entry.has("parameters"))
            for (const auto& [name, value] : entry["parameters"].members()) {
                const int k = face.findParameter(name);
                if (k < 0) value.fail("unknown parameter '" + name + "'");
                const auto& p = face.parameters[static_cast<std::size_t>(k)];
                const double x = value.number();
                if (x < p.min || x > p.max)
                    value.fail("value " + formatDouble(x) + " is outside [" + formatDouble(p.min) + ", " +
                               formatDouble(p.max) + "]");
                v.values.emplace_back(name, x);
            }
        visemes.push_back(std::move(v));
    }
    return visemes;
}

std::vector<VisemeParameters> readVisemeFile(const std::filesystem::path& path,
                                             const DeformationCascade& face) {
    return parseVisemeFile(readFileToString(path), path.string(), face);
}

std::vector<std::string> bundledVisemeSetNames() {
    return {"oculus", "arpabet"};
}

std::filesystem::path arpabetVisemeFilePath(const std::filesystem::path& assetsDir) {
    return assetsDir / "phonemes" / "arpabet_face.json";
}

std::vector<VisemeParameters> bundledVisemeSet(std::string_view name, const std::filesystem::path& assetsDir,
                                               const DeformationCascade& face, std::string_view where) {
    if (name == "oculus") return oculusVisemes();
    if (name == "arpabet") return readVisemeFile(arpabetVisemeFilePath(assetsDir), face);
    std::string valid;
    for (const auto& n : bundledVisemeSetNames()) valid += (valid.empty() ? "" : ", ") + n;
    throwInputError(where, "unknown viseme set '" + std::string(name) + "' (valid: " + valid + ")");
}

} // namespace vl
