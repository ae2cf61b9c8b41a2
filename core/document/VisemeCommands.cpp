#include "core/document/VisemeCommands.h"

#include "core/document/AvatarDocument.h"
#include "core/gltf/AvatarScan.h"

#include "core/common/Error.h"
#include "core/deform/CascadeSampler.h"
#include "core/document/CommandSupport.h"
#include "core/face/HeadParts.h"

#include <algorithm>
#include <cmath>

namespace vl::edit {
namespace {

using detail::checked;
using detail::checkedIndex;
using detail::refuseAvatar;
using detail::requireFace;
using detail::requireSet;

std::string quoted(const std::string& name) {
    return "'" + name + "'";
}

auto findPreset(std::vector<VisemeParameters>& presets, const std::string& name) {
    return std::find_if(presets.begin(), presets.end(),
                        [&](const VisemeParameters& preset) { return preset.name == name; });
}

bool hasPreset(const FaceModel& face, const std::string& name) {
    if (!face.cascade) return false;
    std::vector<VisemeParameters> presets = facePresets(face);
    return findPreset(presets, name) != presets.end();
}

// Every name in the document that refers to viseme `from` refers to `to` afterwards.
void renameEverywhere(Document& next, const std::string& from, const std::string& to) {
    for (auto& [name, value] : next.frequencies.visemeFrequencies.entries)
        if (name == from) name = to;
    for (auto& [phoneme, viseme] : next.frequencies.map.entries)
        if (viseme == from) viseme = to;
    std::replace(next.constraints.pinned.begin(), next.constraints.pinned.end(), from, to);
    if (next.restViseme == from) next.restViseme = to;
    for (auto* pairs : {&next.constraints.apart, &next.constraints.together})
        for (auto& [a, b] : *pairs) {
            if (a == from) a = to;
            if (b == from) b = to;
        }
    if (hasPreset(next.face, from)) {
        next.face.presets = facePresets(next.face);
        findPreset(next.face.presets, from)->name = to;
    }
}

// Direct frequencies and presets listed in the set's order (names outside the set keep their
// relative order after those in it).
template <class Entries, class NameOf>
void followSetOrder(Entries& entries, const VisemeSet& set, NameOf nameOf) {
    const auto rank = [&](const auto& entry) {
        const int index = set.find(nameOf(entry));
        return index < 0 ? static_cast<int>(set.size()) : index;
    };
    std::stable_sort(entries.begin(), entries.end(),
                     [&](const auto& a, const auto& b) { return rank(a) < rank(b); });
}

// The face at parameters q on the set's own mesh (its (u,v) and triangles). A whole-head set (as
// `visemes` writes it: the skin, then the parts in their (u,v) tiles) gets its parts from
// face::HeadParts, which carries them with the jaw and skull rather than sampling the skin there.
std::vector<Vec3> faceOnSetMesh(const Document& document, const std::vector<double>& q) {
    const DeformationCascade& cascade = *document.face.cascade;
    const std::vector<Vec2>& uvs = document.visemes->neutral.uvs;
    const std::vector<face::HeadPart> parts = face::makeHeadParts(cascade);
    const face::HeadPartsSampler partSampler(cascade, parts);
    const std::size_t partCount = partSampler.vertexCount();
    if (partCount > 0 && uvs.size() > partCount && uvs[uvs.size() - partCount][0] >= 1.0 &&
        uvs[uvs.size() - partCount - 1][0] <= 1.0) {
        const std::vector<Vec2> skinUvs(uvs.begin(), uvs.end() - static_cast<std::ptrdiff_t>(partCount));
        std::vector<Vec3> head = CascadeSampler(cascade, skinUvs).evaluate(q);
        const std::vector<Vec3> partPositions = partSampler.evaluate(q);
        head.insert(head.end(), partPositions.begin(), partPositions.end());
        return head;
    }
    return CascadeSampler(cascade, uvs).evaluate(q);
}

// Inserts viseme `viseme` (from `file`) at `index`, with the same bookkeeping as edit::addViseme.
void insertViseme(Document& next, std::size_t index, Viseme viseme, const std::filesystem::path& file) {
    auto set = std::make_shared<VisemeSet>(*next.visemes);
    set->visemes.insert(set->visemes.begin() + static_cast<std::ptrdiff_t>(index), std::move(viseme));
    next.visemeFiles.insert(next.visemeFiles.begin() + static_cast<std::ptrdiff_t>(index), file);
    next.visemes = std::move(set);
}

} // namespace

void checkNewVisemeName(const Document& document, const std::string& name, std::string_view where) {
    if (name.empty()) throwInputError(where, "the viseme needs a name");
    if (std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; }))
        throwInputError(where, "the name " + quoted(name) + " contains a control character");
    if (name.front() == ' ' || name.back() == ' ')
        throwInputError(where, "the name " + quoted(name) + " starts or ends with a space");
    if (name.find('+') != std::string::npos)
        throwInputError(where, "'+' is reserved for merged visemes (their members joined by '+')");
    if (document.visemes && document.visemes->find(name) >= 0)
        throwInputError(where, "a viseme named " + quoted(name) + " already exists");
    if (hasPreset(document.face, name))
        throwInputError(where, "the face has a preset named " + quoted(name) + " already");
}

Document renameViseme(const Document& document, int index, const std::string& name) {
    requireSet(document, "rename viseme");
    refuseAvatar(document, "rename viseme");
    const std::size_t i = checkedIndex(index, document.visemeCount(), "rename viseme");
    const std::string old = document.visemes->visemes[i].name;
    if (name == old) throwInputError("rename " + old, "the new name is the same");
    checkNewVisemeName(document, name, "rename " + old);
    Document next = document;
    auto set = std::make_shared<VisemeSet>(*document.visemes);
    set->visemes[i].name = name;
    next.visemes = std::move(set);
    renameEverywhere(next, old, name);
    return checked(std::move(next));
}

Document duplicateViseme(const Document& document, int index, const std::string& name) {
    requireSet(document, "duplicate viseme");
    refuseAvatar(document, "duplicate viseme");
    const std::size_t i = checkedIndex(index, document.visemeCount(), "duplicate viseme");
    const Viseme& original = document.visemes->visemes[i];
    checkNewVisemeName(document, name, "duplicate " + original.name);
    Document next = document;
    Viseme copy = original;
    copy.name = name;
    insertViseme(next, i + 1, std::move(copy), document.visemeFiles[i]);
    if (!next.frequencies.isPhonemeBased()) {
        auto& entries = next.frequencies.visemeFrequencies.entries;
        const double* value = document.frequencies.visemeFrequencies.find(original.name);
        entries.emplace_back(name, value ? *value : 1.0);
        followSetOrder(entries, *next.visemes, [](const auto& entry) { return entry.first; });
    }
    if (hasPreset(document.face, original.name)) {
        next.face.presets = facePresets(document.face);
        VisemeParameters preset = *findPreset(next.face.presets, original.name);
        preset.name = name;
        next.face.presets.push_back(std::move(preset));
        followSetOrder(next.face.presets, *next.visemes, [](const auto& p) { return p.name; });
    }
    return checked(std::move(next));
}

Document moveViseme(const Document& document, int from, int to) {
    requireSet(document, "move viseme");
    refuseAvatar(document, "move viseme");
    const std::size_t a = checkedIndex(from, document.visemeCount(), "move viseme");
    const std::size_t b = checkedIndex(to, document.visemeCount(), "move viseme to");
    if (a == b) throwInputError("move " + document.visemes->visemes[a].name, "it is already there");
    Document next = document;
    auto set = std::make_shared<VisemeSet>(*document.visemes);
    const auto rotate = [&](auto& items) {
        if (a < b)
            std::rotate(items.begin() + static_cast<std::ptrdiff_t>(a),
                        items.begin() + static_cast<std::ptrdiff_t>(a + 1),
                        items.begin() + static_cast<std::ptrdiff_t>(b + 1));
        else
            std::rotate(items.begin() + static_cast<std::ptrdiff_t>(b),
                        items.begin() + static_cast<std::ptrdiff_t>(a),
                        items.begin() + static_cast<std::ptrdiff_t>(a + 1));
    };
    rotate(set->visemes);
    rotate(next.visemeFiles);
    next.visemes = std::move(set);
    followSetOrder(next.frequencies.visemeFrequencies.entries, *next.visemes,
                   [](const auto& entry) { return entry.first; });
    if (hasPreset(next.face, next.visemes->visemes[b].name)) {
        next.face.presets = facePresets(next.face);
        followSetOrder(next.face.presets, *next.visemes, [](const auto& p) { return p.name; });
    }
    return checked(std::move(next));
}

Document addRestViseme(const Document& document, const std::string& name) {
    requireSet(document, "rest viseme");
    refuseAvatar(document, "rest viseme");
    checkNewVisemeName(document, name, "rest viseme");
    Document next = document;
    insertViseme(next, next.visemeCount(), Viseme{name, document.visemes->neutral.positions}, {});
    if (!next.frequencies.isPhonemeBased())
        next.frequencies.visemeFrequencies.entries.emplace_back(name, 1.0);
    return checked(std::move(next));
}

Document setVisemeShape(const Document& document, int index, std::vector<Vec3> positions) {
    requireSet(document, "sculpt viseme");
    const std::size_t i = checkedIndex(index, document.visemeCount(), "sculpt viseme");
    const std::string where = "sculpt " + document.visemes->visemes[i].name;
    if (positions.size() != document.visemes->vertexCount())
        throwInputError(where, "the shape has " + std::to_string(positions.size()) +
                                   " vertices, the neutral " +
                                   std::to_string(document.visemes->vertexCount()));
    for (const Vec3& p : positions)
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throwInputError(where, "the shape has a position that is not a finite number");
    if (document.avatar.isSet()) {
        // An avatar's viseme is its targets: a mesh without a target of it keeps the file's vertices
        // (the writer replaces targets, never adds one; AvatarWriter.h).
        const AvatarScan& scan = *document.avatar.scan;
        const std::vector<char> movable = avatarSculptableVertices(scan, i);
        if (std::find(movable.begin(), movable.end(), 1) == movable.end())
            throwInputError(where, "no mesh of the avatar has a target of it (a rest viseme added to the "
                                   "avatar is its base mesh)");
        const std::vector<Vec3>& file = scan.set.visemes[i].positions;
        for (std::size_t v = 0; v < positions.size(); ++v)
            if (!movable[v]) positions[v] = file[v];
    }
    Document next = document;
    auto set = std::make_shared<VisemeSet>(*next.visemes);
    set->visemes[i].positions = std::move(positions);
    next.visemes = std::move(set);
    next.visemeFiles[i].clear(); // embedded: the file no longer holds this shape
    return checked(std::move(next));
}

Document addBlendedViseme(const Document& document, const std::string& name,
                          const std::vector<std::pair<int, double>>& mix) {
    requireSet(document, "blend visemes");
    refuseAvatar(document, "blend visemes");
    checkNewVisemeName(document, name, "blend visemes");
    if (mix.empty()) throwInputError("blend visemes", "select at least one viseme to blend");
    const VisemeSet& set = *document.visemes;
    std::vector<Vec3> positions = set.neutral.positions;
    std::size_t last = 0;
    for (const auto& [index, weight] : mix) {
        const std::size_t i = checkedIndex(index, set.size(), "blend visemes");
        if (!std::isfinite(weight))
            throwInputError("blend visemes",
                            "the weight of " + set.visemes[i].name + " is not a finite number");
        for (std::size_t v = 0; v < positions.size(); ++v)
            positions[v] += weight * (set.visemes[i].positions[v] - set.neutral.positions[v]);
        last = std::max(last, i);
    }
    Document next = document;
    insertViseme(next, last + 1, Viseme{name, std::move(positions)}, {});
    if (!next.frequencies.isPhonemeBased()) {
        auto& entries = next.frequencies.visemeFrequencies.entries;
        entries.emplace_back(name, 1.0);
        followSetOrder(entries, *next.visemes, [](const auto& entry) { return entry.first; });
    }
    return checked(std::move(next));
}

std::vector<VisemeParameters> facePresets(const FaceModel& face) {
    return face.presets.empty() ? oculusVisemes() : face.presets;
}

bool visemeSetMadeByFace(const Document& document) {
    if (!document.visemes || !document.face.cascade) return false;
    const MeshData& neutral = document.visemes->neutral;
    if (!neutral.hasUVs() || neutral.uvs.size() != neutral.positions.size()) return false;
    const std::vector<Vec3> face = faceOnSetMesh(document, document.face.cascade->defaults());
    // The set's files round positions and (u,v) (6 digits in OBJ): a tolerance relative to its size.
    Vec3 lo, hi;
    if (!bounds(neutral.positions, lo, hi)) return false;
    const double tolerance = 1e-4 * std::max((hi - lo).norm(), 1e-12);
    for (std::size_t i = 0; i < face.size(); ++i)
        if (!((face[i] - neutral.positions[i]).norm() <= tolerance)) return false;
    return true;
}

std::vector<std::vector<double>> visemeFaceParameters(const Document& document) {
    if (!visemeSetMadeByFace(document)) return {};
    const DeformationCascade& cascade = *document.face.cascade;
    const std::vector<VisemeParameters> presets = facePresets(document.face);
    std::vector<std::vector<double>> out;
    for (const Viseme& viseme : document.visemes->visemes) {
        const auto preset = std::find_if(presets.begin(), presets.end(),
                                         [&](const VisemeParameters& p) { return p.name == viseme.name; });
        out.push_back(preset == presets.end() ? cascade.defaults() : parameterVector(cascade, *preset));
    }
    return out;
}

VisemeParameters presetOfSliders(const FaceModel& face, const std::string& name) {
    VisemeParameters preset{name, {}};
    const auto& parameters = face.cascade->parameters;
    for (std::size_t k = 0; k < parameters.size(); ++k)
        if (face.parameters[k] != parameters[k].defaultValue)
            preset.values.emplace_back(parameters[k].name, face.parameters[k]);
    return preset;
}

Document storeSlidersAsNewViseme(const Document& document, const std::string& name) {
    requireFace(document, "store sliders");
    checkNewVisemeName(document, name, "store sliders as " + quoted(name));
    Document next = document;
    next.face.presets = facePresets(document.face);
    next.face.presets.push_back(presetOfSliders(document.face, name));
    if (visemeSetMadeByFace(document)) {
        insertViseme(next, next.visemeCount(),
                     Viseme{name, faceOnSetMesh(document, document.face.parameters)}, {});
        if (!next.frequencies.isPhonemeBased())
            next.frequencies.visemeFrequencies.entries.emplace_back(name, 1.0);
    }
    return checked(std::move(next));
}

Document storeSlidersInViseme(const Document& document, const std::string& name) {
    requireFace(document, "store sliders");
    const std::string where = "store sliders in " + quoted(name);
    const int index = document.visemes ? document.visemes->find(name) : -1;
    const bool faceSet = visemeSetMadeByFace(document);
    if (!hasPreset(document.face, name) && !(index >= 0 && faceSet))
        throwInputError(where, "no preset or viseme of the face has that name (store as a new viseme)");
    Document next = document;
    next.face.presets = facePresets(document.face);
    VisemeParameters preset = presetOfSliders(document.face, name);
    if (const auto it = findPreset(next.face.presets, name); it != next.face.presets.end())
        *it = std::move(preset);
    else
        next.face.presets.push_back(std::move(preset));
    if (index >= 0 && faceSet) {
        auto set = std::make_shared<VisemeSet>(*document.visemes);
        Viseme& viseme = set->visemes[static_cast<std::size_t>(index)];
        viseme.positions = faceOnSetMesh(document, document.face.parameters);
        next.visemes = std::move(set);
        next.visemeFiles[static_cast<std::size_t>(index)].clear(); // embedded from now on
    }
    return checked(std::move(next));
}

Document removePreset(const Document& document, const std::string& name) {
    requireFace(document, "remove preset");
    if (!hasPreset(document.face, name)) throwInputError("remove preset", "no preset named " + quoted(name));
    if (document.visemes && document.visemes->find(name) >= 0 && visemeSetMadeByFace(document))
        throwInputError("remove preset " + quoted(name),
                        "it is the viseme " + quoted(name) + " of the face's set: remove the viseme instead");
    Document next = document;
    next.face.presets = facePresets(document.face);
    next.face.presets.erase(findPreset(next.face.presets, name));
    if (next.face.presets.empty())
        throwInputError("remove preset " + quoted(name), "the face keeps at least one preset");
    return checked(std::move(next));
}

} // namespace vl::edit
