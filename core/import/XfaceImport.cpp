#include "core/import/XfaceImport.h"

#include "core/common/AtomicFile.h"
#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/io/MeshIO.h"

#include <tinyxml2.h>

#include <algorithm>
#include <unordered_set>

namespace vl {
namespace {

std::string attribute(const tinyxml2::XMLElement* e, const char* name) {
    const char* value = e->Attribute(name);
    return value ? value : "";
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

XfaceFace loadXfaceFace(const std::filesystem::path& fdpPath) {
    const FdpDocument doc = parseFdp(readFileToString(fdpPath), fdpPath.string());
    if (doc.entities.empty()) throwInputError(fdpPath.string(), "no entities in <source>");
    const FdpEntity* neutral = &doc.entities.front();
    for (const FdpEntity& e : doc.entities)
        if (e.alias == kXfaceRestAlias) neutral = &e;

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
