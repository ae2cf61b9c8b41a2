#include "core/export/Xface.h"

#include "core/common/Error.h"
#include "core/common/MarkupEscape.h"
#include "core/common/TextParsing.h"
#include "core/export/KeyMeshFiles.h"
#include "core/import/XfaceImport.h"

#include <algorithm>
#include <cctype>
#include <set>

namespace vl {
namespace {

constexpr const char* kPausePhonemes[] = {"#", "_"};

// Rough MPEG-4 FAPU distances as fractions of the head's width (ratios of a typical face), so
// XfacePlayer has sensible units before a designer places the feature points in XfaceEd.
std::vector<std::pair<std::string, double>> estimatedFapu(const MeshData& neutral) {
    Vec3 lo, hi;
    bounds(neutral.positions, lo, hi);
    const double width = hi[0] - lo[0];
    return {{"ENS0", 0.22 * width},
            {"ES0", 0.30 * width},
            {"IRISD0", 0.07 * width},
            {"MNS0", 0.13 * width},
            {"MW0", 0.22 * width}};
}

} // namespace

std::vector<std::string> xfaceAliases(const ReducedModel& model) {
    std::vector<std::string> aliases;
    std::set<std::string> used{kXfaceRestAlias};
    for (const KeyMesh& key : model.keys) {
        std::string alias = key.name;
        for (char& c : alias)
            if (std::isspace(static_cast<unsigned char>(c)) || c == '"' || c == '<' || c == '>' || c == '&')
                c = '_';
        std::string unique = alias;
        for (int suffix = 2; used.count(unique); ++suffix) unique = alias + "_" + std::to_string(suffix);
        used.insert(unique);
        aliases.push_back(unique);
    }
    return aliases;
}

std::string formatFdp(const ReducedModel& model) {
    validateReducedModel(model, "Xface export");
    const std::vector<std::string> aliases = xfaceAliases(model);
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\" ?>\n<xfdp>\n\n";
    out += "  <!--MPEG-4 FDP specification file written by VisemeLab: " + std::to_string(model.keys.size()) +
           " merged visemes-->\n\n  <head>\n    <file version=\"0.2\"/>\n";
    out += "    <!--FAPU estimated from the neutral mesh's width: set the feature points in XfaceEd-->\n    "
           "<fapu";
    for (const auto& [name, value] : estimatedFapu(model.neutral))
        out += " " + name + "=\"" + formatDouble(value) + "\"";
    out += "/>\n    <translation x=\"0\" y=\"0\" z=\"0\"/>\n";
    out +=
        "    <rotation axis_angle=\"0\" axis_x=\"0\" axis_y=\"1\" axis_z=\"0\"/>\n  </head>\n\n  <source>\n";
    auto entity = [&](const std::string& alias, const char* category, const std::string& file) {
        out += "    <entity alias=\"" + escapeMarkup(alias) + "\" category=\"" + category +
               "\">\n      <mesh file=\"" + escapeMarkup(file) + "\" format=\"wrl\"/>\n    </entity>\n";
    };
    entity(kXfaceRestAlias, "Expression", neutralFileName(".wrl"));
    for (std::size_t k = 0; k < model.keys.size(); ++k)
        entity(aliases[k], "Viseme", keyFileName(model, k, ".wrl"));
    out += "  </source>\n\n</xfdp>\n";
    return out;
}

std::string formatXfaceDictionary(const ReducedModel& model, std::string_view language) {
    validateReducedModel(model, "Xface export");
    const std::vector<std::string> aliases = xfaceAliases(model);
    std::string out = std::string(language) + "\n";
    std::string silence = kXfaceRestAlias;
    for (const auto& [phoneme, key] : model.phonemeToKey) {
        for (char c : phoneme)
            if (std::isspace(static_cast<unsigned char>(c)))
                throwInputError("Xface export", "phoneme '" + phoneme + "' contains white space");
        // A resting phoneme (rest-free model) shows the neutral face.
        const std::string alias =
            key == kRestingKey ? std::string(kXfaceRestAlias) : aliases[static_cast<std::size_t>(key)];
        out += phoneme + " " + alias + "\n";
        if (phoneme == "sil") silence = alias;
    }
    // Pauses need a line, or XfacePlayer finds no viseme for them: '#' as in Xface's own dictionaries
    // (italian.dic: "# Rest"), '_' as in the MBROLA phoneme timings it plays. Silence shows the key
    // "sil" was merged into, else the neutral face.
    for (const char* pause : kPausePhonemes)
        if (std::none_of(model.phonemeToKey.begin(), model.phonemeToKey.end(),
                         [&](const auto& entry) { return entry.first == pause; }))
            out += std::string(pause) + " " + silence + "\n";
    return out;
}

std::vector<std::string> addXfaceFace(OutputSet& outputs, const ReducedModel& model,
                                      std::string_view faceName) {
    const std::string dictionary = formatXfaceDictionary(model);
    const std::string fdp = formatFdp(model);
    std::vector<std::string> names = addKeyMeshFiles(outputs, model, ".wrl");
    names.push_back(std::string(faceName) + ".fdp");
    outputs.add(names.back(), fdp);
    names.push_back(std::string(faceName) + ".dic");
    outputs.add(names.back(), dictionary);
    return names;
}

std::vector<std::string> writeXfaceFace(const std::filesystem::path& outDir, const ReducedModel& model,
                                        std::string_view faceName) {
    OutputSet outputs(outDir, "export-vrml"); // the meshes, .fdp and .dic replace the last export as one set
    std::vector<std::string> names = addXfaceFace(outputs, model, faceName);
    outputs.commit();
    return names;
}

} // namespace vl
