// EditorSession: viseme authoring and the phoneme map editor, each a validated command of the core
// (core/document/VisemeCommands.h, PhonemeMapCommands.h) committed as one undo step.
#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/document/VisemeCommands.h"
#include "core/phonetics/PhonemeMaps.h"
#include "core/phonetics/PhonemeTableIO.h"
#include "ui/session/EditorSession.h"

namespace vl::ui {
namespace {

std::string quoted(const std::string& name) {
    return "'" + name + "'";
}

} // namespace

void EditorSession::select(const std::string& name) {
    selectedViseme = visemes() && !name.empty() ? visemes()->find(name) : -1;
}

void EditorSession::renameViseme(int index, const std::string& name) {
    Document next = edit::renameViseme(document(), index, name);
    const std::string old = visemes()->visemes[static_cast<std::size_t>(index)].name;
    commit("Rename " + old + " to " + name, std::move(next));
}

void EditorSession::duplicateViseme(int index, const std::string& name) {
    Document next = edit::duplicateViseme(document(), index, name);
    commit("Duplicate " + visemes()->visemes[static_cast<std::size_t>(index)].name + " as " + name,
           std::move(next));
    select(name);
}

void EditorSession::sculptViseme(int index, std::vector<Vec3> positions, SculptTool tool) {
    Document next = edit::setVisemeShape(document(), index, std::move(positions));
    const std::string& name = visemes()->visemes[static_cast<std::size_t>(index)].name;
    commit("Sculpt " + name + " (" + std::string(sculptToolName(tool)) + ")", std::move(next),
           "sculpt:" + name);
}

void EditorSession::addBlendedViseme(const std::string& name,
                                     const std::vector<std::pair<int, double>>& mix) {
    commit("Blend " + name, edit::addBlendedViseme(document(), name, mix));
    select(name);
}

void EditorSession::moveViseme(int from, int to) {
    Document next = edit::moveViseme(document(), from, to);
    const std::string name = visemes()->visemes[static_cast<std::size_t>(from)].name;
    const std::string selected = selectedViseme >= 0
                                     ? visemes()->visemes[static_cast<std::size_t>(selectedViseme)].name
                                     : std::string();
    commit("Move " + name + (to < from ? " up" : " down"), std::move(next));
    select(selected);
}

void EditorSession::addRestViseme(const std::string& name) {
    commit("Add rest viseme " + name, edit::addRestViseme(document(), name));
    select(name);
}

void EditorSession::storeSlidersAsNewViseme(const std::string& name) {
    const std::size_t before = visemeCount();
    commit("Store sliders as " + name, edit::storeSlidersAsNewViseme(document(), name));
    if (visemeCount() > before) {
        select(name);
        info("Stored the sliders as the new viseme " + quoted(name) + " (preset and mesh)");
    } else {
        info("Stored the sliders as the preset " + quoted(name) +
             (visemes() ? ": the viseme set is not this face's, generate it from the face to get the mesh"
                        : ": generate the viseme set from the face to get its mesh"));
    }
}

void EditorSession::storeSlidersInViseme(const std::string& name) {
    const auto set = document().visemes;
    commit("Store sliders in " + name, edit::storeSlidersInViseme(document(), name));
    info(set != document().visemes
             ? "Stored the sliders in " + quoted(name) + ": preset and mesh regenerated"
             : "Stored the sliders in the preset " + quoted(name) + " (no mesh of the face)");
}

void EditorSession::removePreset(const std::string& name) {
    commit("Remove preset " + name, edit::removePreset(document(), name));
}

bool EditorSession::visemeSetMadeByFace() {
    const Document& current = document();
    if (madeByFace_.set != current.visemes || madeByFace_.cascade != current.face.cascade ||
        madeByFace_.presets != current.face.presets) {
        madeByFace_ = {current.visemes, current.face.cascade, current.face.presets,
                       edit::visemeSetMadeByFace(current), edit::visemeFaceParameters(current)};
    }
    return madeByFace_.value;
}

const std::vector<std::vector<double>>& EditorSession::visemeFaceParameters() {
    visemeSetMadeByFace(); // brings the cache up to date
    return madeByFace_.parameters;
}

FrequencyTable EditorSession::startingPhonemeTable() const {
    if (document().frequencies.isPhonemeBased()) return document().frequencies.phonemes;
    return loadPhonemeTable(defaultPhonemeTablePath(assetsDirectory()));
}

void EditorSession::startPhonemeMap(FrequencyTable table, const PhonemeVisemeMap& start,
                                    const std::vector<edit::MapAssignment>& assignment,
                                    const std::string& startName) {
    commit("Phoneme map from " + startName,
           edit::startPhonemeMap(document(), std::move(table), start, assignment));
}

void EditorSession::movePhonemes(const std::string& from, const std::string& to) {
    commit("Map the phonemes of " + from + " to " + to, edit::movePhonemes(document(), from, to));
}

void EditorSession::useDirectFrequencies() {
    commit("Direct viseme frequencies", edit::useDirectFrequencies(document()));
}

void EditorSession::savePhonemeMap(const std::filesystem::path& file) const {
    if (!document().frequencies.isPhonemeBased())
        throwInputError(file.string(), "the frequencies are direct: there is no phoneme map to save");
    vl::savePhonemeMap(file, document().frequencies.map);
}

} // namespace vl::ui
