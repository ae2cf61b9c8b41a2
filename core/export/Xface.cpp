#include "core/export/Xface.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/MarkupEscape.h"
#include "core/common/TextParsing.h"
#include "core/export/KeyMeshFiles.h"
#include "core/io/MeshIO.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <unordered_set>

namespace vl {
namespace {

constexpr const char* kRestAlias = "Rest";
constexpr const char* kPausePhonemes[] = {"#", "_"};

std::string attribute(const tinyxml2::XMLElement* e, const char* name) {
    const char* value = e->Attribute(name);
    return value ? value : "";
}

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

MeshData appendMesh(MeshData into, const MeshData& part) {
    const auto base = static_cast<std::uint32_t>(into.positions.size());
    if (into.hasUVs() != part.hasUVs() && !into.positions.empty())
        throwInputError("mesh", "some meshes of the entity have texture coordinates and some not");
    into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
    into.uvs.insert(into.uvs.end(), part.uvs.begin(), part.uvs.end());
    for (Triangle t : part.triangles) into.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    return into;
}

MeshData readEntityMeshes(const FdpEntity& entity, const std::filesystem::path& fdpPath) {
    const std::string where =
        fileLine(fdpPath.string(), static_cast<std::size_t>(entity.line)) + ": entity '" + entity.alias + "'";
    MeshData mesh;
    for (const std::string& file : entity.meshFiles) {
        const std::filesystem::path path = fdpPath.parent_path() / file;
        if (!std::filesystem::exists(path))
            throwInputError(where, "mesh file '" + file + "' not found (looked for " + path.string() + ")");
        try {
            mesh = appendMesh(std::move(mesh), readMesh(path));
        } catch (const InputError& e) {
            throwInputError(where, e.what());
        }
        // An entity may list the same mesh many times: its parts together obey the viseme set limit.
        checkVisemeSetSize(0, mesh.positions.size(), where);
    }
    return mesh;
}

} // namespace

FdpDocument parseFdp(std::string_view text, std::string_view source) {
    tinyxml2::XMLDocument xml;
    if (xml.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS)
        throwInputError(fileLine(source, static_cast<std::size_t>(xml.ErrorLineNum())),
                        std::string("malformed XML: ") + xml.ErrorStr());
    const tinyxml2::XMLElement* root = xml.FirstChildElement("xfdp");
    if (!root) throwInputError(source, "not an Xface face definition (no <xfdp> element)");
    FdpDocument doc;
    if (const auto* head = root->FirstChildElement("head")) {
        if (const auto* file = head->FirstChildElement("file")) doc.fileVersion = attribute(file, "version");
        if (const auto* fapu = head->FirstChildElement("fapu"))
            for (const auto* a = fapu->FirstAttribute(); a; a = a->Next())
                doc.fapu.emplace_back(
                    a->Name(),
                    parseFiniteDouble(a->Value(),
                                      fileLine(source, static_cast<std::size_t>(fapu->GetLineNum())) +
                                          ": fapu " + a->Name()));
    }
    const tinyxml2::XMLElement* sourceElement = root->FirstChildElement("source");
    if (!sourceElement) throwInputError(source, "no <source> element (the face's mesh entities)");
    for (const auto* e = sourceElement->FirstChildElement("entity"); e; e = e->NextSiblingElement("entity")) {
        FdpEntity entity;
        entity.line = e->GetLineNum();
        const std::string where = fileLine(source, static_cast<std::size_t>(entity.line));
        entity.alias = attribute(e, "alias");
        entity.category = attribute(e, "category");
        if (entity.alias.empty()) throwInputError(where, "entity without an alias");
        for (const auto* m = e->FirstChildElement("mesh"); m; m = m->NextSiblingElement("mesh")) {
            const std::string file = attribute(m, "file");
            if (file.empty())
                throwInputError(fileLine(source, static_cast<std::size_t>(m->GetLineNum())),
                                "entity '" + entity.alias + "': <mesh> without a file");
            entity.meshFiles.push_back(file);
            entity.meshFormats.push_back(attribute(m, "format"));
        }
        if (entity.meshFiles.empty()) throwInputError(where, "entity '" + entity.alias + "' has no <mesh>");
        doc.entities.push_back(std::move(entity));
    }
    return doc;
}

std::vector<std::string> xfaceAliases(const ReducedModel& model) {
    std::vector<std::string> aliases;
    std::set<std::string> used{kRestAlias};
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
    entity(kRestAlias, "Expression", neutralFileName(".wrl"));
    for (std::size_t k = 0; k < model.keys.size(); ++k)
        entity(aliases[k], "Viseme", keyFileName(model, k, ".wrl"));
    out += "  </source>\n\n</xfdp>\n";
    return out;
}

PhonemeVisemeMap parseXfaceDictionary(std::string_view text, std::string_view source, std::string* language) {
    PhonemeVisemeMap map;
    map.origin.text = source;
    std::unordered_set<std::string_view> listed; // linear-time duplicate check
    text = stripUtf8Bom(text); // a file of only a byte order mark is empty, not the language "\xEF\xBB\xBF"
    std::size_t lineNumber = 0, start = 0;
    bool haveLanguage = false;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::string_view line = trim(text.substr(start, end - start));
        start = end + 1;
        ++lineNumber;
        if (line.empty()) continue;
        const auto tokens = splitWhitespace(line);
        if (!haveLanguage) {
            if (tokens.size() != 1)
                throwInputError(fileLine(source, lineNumber), "expected the language name");
            if (language) *language = std::string(tokens[0]);
            haveLanguage = true;
            continue;
        }
        if (tokens.size() != 2) throwInputError(fileLine(source, lineNumber), "expected 'phoneme viseme'");
        if (!listed.insert(tokens[0]).second)
            throwInputError(fileLine(source, lineNumber),
                            "phoneme '" + std::string(tokens[0]) + "' is listed twice");
        map.entries.emplace_back(std::string(tokens[0]), std::string(tokens[1]));
    }
    if (!haveLanguage) throwInputError(source, "empty phoneme dictionary");
    if (map.entries.empty()) throwInputError(source, "no 'phoneme viseme' lines after the language line");
    return map;
}

std::string formatXfaceDictionary(const ReducedModel& model, std::string_view language) {
    validateReducedModel(model, "Xface export");
    const std::vector<std::string> aliases = xfaceAliases(model);
    std::string out = std::string(language) + "\n";
    std::string silence = kRestAlias;
    for (const auto& [phoneme, key] : model.phonemeToKey) {
        for (char c : phoneme)
            if (std::isspace(static_cast<unsigned char>(c)))
                throwInputError("Xface export", "phoneme '" + phoneme + "' contains white space");
        // A resting phoneme (rest-free model) shows the neutral face.
        const std::string alias =
            key == kRestingKey ? std::string(kRestAlias) : aliases[static_cast<std::size_t>(key)];
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

XfaceFace loadXfaceFace(const std::filesystem::path& fdpPath) {
    const FdpDocument doc = parseFdp(readFileToString(fdpPath), fdpPath.string());
    if (doc.entities.empty()) throwInputError(fdpPath.string(), "no entities in <source>");
    const FdpEntity* neutral = &doc.entities.front();
    for (const FdpEntity& e : doc.entities)
        if (e.alias == kRestAlias) neutral = &e;

    XfaceFace face;
    face.set.neutral = readEntityMeshes(*neutral, fdpPath);
    face.set.neutralSource = fdpPath.parent_path() / neutral->meshFiles.front();
    std::size_t visemeCount = 0;
    for (const FdpEntity& e : doc.entities) visemeCount += e.category == "Viseme" ? 1 : 0;
    // Checked before reading: entities naming the same big mesh again and again must not exhaust memory.
    checkVisemeSetSize(visemeCount, face.set.vertexCount(), fdpPath.string());
    std::unordered_set<std::string_view> aliases;
    for (const FdpEntity& e : doc.entities) {
        if (e.category != "Viseme") continue;
        const std::string where = fileLine(fdpPath.string(), static_cast<std::size_t>(e.line));
        if (!aliases.insert(e.alias).second)
            throwInputError(where, "viseme '" + e.alias + "' is defined twice");
        const MeshData mesh = readEntityMeshes(e, fdpPath);
        checkInterpolable(face.set.neutral, face.set.neutralSource.string(), mesh,
                          where + ": entity '" + e.alias + "'");
        face.set.visemes.push_back({e.alias, mesh.positions});
    }
    if (face.set.visemes.size() < 2)
        throwInputError(fdpPath.string(), "needs at least 2 entities with category=\"Viseme\", found " +
                                              std::to_string(face.set.visemes.size()));
    std::filesystem::path dictionary = fdpPath;
    dictionary.replace_extension(".dic");
    if (std::filesystem::exists(dictionary)) {
        for (auto& entry : parseXfaceDictionary(readFileToString(dictionary), dictionary.string()).entries) {
            if (entry.second == neutral->alias)
                face.restPhonemes.push_back(std::move(entry.first));
            else
                face.dictionary.entries.push_back(std::move(entry));
        }
    }
    return face;
}

} // namespace vl
