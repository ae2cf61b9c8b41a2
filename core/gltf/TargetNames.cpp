#include "core/gltf/TargetNames.h"

#include "core/common/Error.h"
#include "core/gltf/GltfDocument.h"

#include <cctype>

namespace vl {
namespace {

char lower(char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

std::string lowered(std::string_view text) {
    std::string out(text);
    for (char& c : out) c = lower(c);
    return out;
}

// Matches the class starting after '[' at pattern[p]; sets `end` to the index after ']'.
bool classMatches(std::string_view pattern, std::size_t p, char c, std::size_t& end) {
    bool negate = false;
    if (p < pattern.size() && (pattern[p] == '!' || pattern[p] == '^')) {
        negate = true;
        ++p;
    }
    bool matched = false;
    bool first = true;
    while (p < pattern.size() && (pattern[p] != ']' || first)) {
        first = false;
        const char lo = lower(pattern[p]);
        char hi = lo;
        if (p + 2 < pattern.size() && pattern[p + 1] == '-' && pattern[p + 2] != ']') {
            hi = lower(pattern[p + 2]);
            p += 2;
        }
        if (lower(c) >= lo && lower(c) <= hi) matched = true;
        ++p;
    }
    end = p + 1; // past ']' (checkGlobPattern guarantees it exists)
    return matched != negate;
}

bool arrayOfStrings(const nlohmann::ordered_json& value) {
    if (!value.is_array()) return false;
    for (const auto& v : value)
        if (!v.is_string()) return false;
    return true;
}

} // namespace

const std::vector<std::string>& oculusVisemeNames() {
    static const std::vector<std::string> names{"sil", "PP", "FF", "TH", "DD", "kk", "CH", "SS",
                                                "nn",  "RR", "aa", "E",  "ih", "oh", "ou"};
    return names;
}

std::optional<std::string> oculusVisemeOf(std::string_view targetName) {
    std::string name = lowered(targetName);
    if (name.rfind("viseme_", 0) == 0) name.erase(0, 7);
    if (name == "i") return "ih";
    if (name == "o") return "oh";
    if (name == "u") return "ou";
    for (const std::string& canonical : oculusVisemeNames())
        if (lowered(canonical) == name) return canonical;
    return std::nullopt;
}

void checkGlobPattern(std::string_view pattern, std::string_view where) {
    if (pattern.empty()) throwInputError(where, "empty target pattern");
    for (std::size_t p = 0; p < pattern.size(); ++p) {
        if (pattern[p] != '[') continue;
        std::size_t q = p + 1;
        if (q < pattern.size() && (pattern[q] == '!' || pattern[q] == '^')) ++q;
        if (q < pattern.size() && pattern[q] == ']') ++q; // a leading ']' is a member
        while (q < pattern.size() && pattern[q] != ']') ++q;
        if (q >= pattern.size())
            throwInputError(where, "unterminated '[' class in pattern '" + std::string(pattern) + "'");
        p = q;
    }
}

bool globMatch(std::string_view pattern, std::string_view name) {
    // Iterative matching with one backtrack point for the last '*': linear in practice.
    std::size_t p = 0, n = 0, starP = std::string_view::npos, starN = 0;
    while (n < name.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            starP = p++;
            starN = n;
            continue;
        }
        if (p < pattern.size()) {
            std::size_t next = p + 1;
            bool ok = false;
            if (pattern[p] == '?')
                ok = true;
            else if (pattern[p] == '[')
                ok = classMatches(pattern, p + 1, name[n], next);
            else
                ok = lower(pattern[p]) == lower(name[n]);
            if (ok) {
                p = next;
                ++n;
                continue;
            }
        }
        if (starP == std::string_view::npos) return false;
        p = starP + 1;
        n = ++starN;
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

std::vector<TargetName> meshTargetNames(const GltfDocument& doc, int mesh) {
    const tinygltf::Mesh& m = doc.model.meshes[static_cast<std::size_t>(mesh)];
    const std::size_t count = m.primitives.empty() ? 0 : m.primitives[0].targets.size();
    const auto& meshJson = doc.json.at("meshes").at(static_cast<std::size_t>(mesh));
    const nlohmann::ordered_json* names = nullptr;
    auto namesIn = [&](const nlohmann::ordered_json& object) -> const nlohmann::ordered_json* {
        const auto extras = object.find("extras");
        if (extras == object.end() || !extras->is_object()) return nullptr;
        const auto it = extras->find("targetNames");
        return it != extras->end() && arrayOfStrings(*it) && it->size() == count ? &*it : nullptr;
    };
    names = namesIn(meshJson);
    if (!names && meshJson.contains("primitives") && meshJson.at("primitives").is_array() &&
        !meshJson.at("primitives").empty())
        names = namesIn(meshJson.at("primitives").at(0));
    std::vector<TargetName> out(count);
    for (std::size_t k = 0; k < count; ++k) {
        if (names) {
            out[k] = {(*names)[k].get<std::string>(), true};
        } else {
            out[k] = {"target" + std::to_string(k), false};
        }
    }
    return out;
}

} // namespace vl
