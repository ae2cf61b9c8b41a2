#include "ui/session/SessionAuthoring.h"

#include "core/common/Error.h"
#include "core/document/Commands.h"
#include "core/document/VisemeCommands.h"
#include "core/io/MeshIO.h"
#include "core/phonetics/PhonemeMaps.h"
#include "ui/session/BundledAssets.h"

namespace vl::ui {
namespace {

std::string quoted(const std::string& name) {
    return "'" + name + "'";
}

} // namespace

void SessionAuthoring::importViseme(const std::string& name, const std::filesystem::path& file) {
    if (!core_.document().visemes) throwInputError(file.string(), "load a neutral mesh or viseme set first");
    core_.commit("Import viseme " + name, edit::addViseme(core_.document(), name, readMesh(file), file));
    core_.messages().info("Imported " + name + " from " + file.string());
}

void SessionAuthoring::removeViseme(int index, const std::string& phonemesGoTo) {
    const std::string name =
        core_.document().visemes && index >= 0 && index < static_cast<int>(core_.document().visemeCount())
            ? core_.document().visemes->visemes[static_cast<std::size_t>(index)].name
            : std::to_string(index);
    const std::string selected = core_.selectedViseme() != index ? core_.selectedVisemeName() : std::string();
    core_.commit("Remove viseme " + name, edit::removeViseme(core_.document(), index, phonemesGoTo));
    core_.selectViseme(selected);
}

void SessionAuthoring::renameViseme(int index, const std::string& name) {
    Document next = edit::renameViseme(core_.document(), index, name);
    const std::string old = core_.document().visemes->visemes[static_cast<std::size_t>(index)].name;
    core_.commit("Rename " + old + " to " + name, std::move(next));
}

void SessionAuthoring::duplicateViseme(int index, const std::string& name) {
    Document next = edit::duplicateViseme(core_.document(), index, name);
    core_.commit("Duplicate " + core_.document().visemes->visemes[static_cast<std::size_t>(index)].name +
                     " as " + name,
                 std::move(next));
    core_.selectViseme(name);
}

void SessionAuthoring::sculptViseme(int index, std::vector<Vec3> positions, SculptTool tool) {
    Document next = edit::setVisemeShape(core_.document(), index, std::move(positions));
    const std::string& name = core_.document().visemes->visemes[static_cast<std::size_t>(index)].name;
    core_.commit("Sculpt " + name + " (" + std::string(sculptToolName(tool)) + ")", std::move(next),
                 "sculpt:" + name);
}

void SessionAuthoring::addBlendedViseme(const std::string& name,
                                        const std::vector<std::pair<int, double>>& mix) {
    core_.commit("Blend " + name, edit::addBlendedViseme(core_.document(), name, mix));
    core_.selectViseme(name);
}

void SessionAuthoring::moveViseme(int from, int to) {
    Document next = edit::moveViseme(core_.document(), from, to);
    const std::string name = core_.document().visemes->visemes[static_cast<std::size_t>(from)].name;
    const std::string selected = core_.selectedVisemeName();
    core_.commit("Move " + name + (to < from ? " up" : " down"), std::move(next));
    core_.selectViseme(selected);
}

void SessionAuthoring::addRestViseme(const std::string& name) {
    core_.commit("Add rest viseme " + name, edit::addRestViseme(core_.document(), name));
    core_.selectViseme(name);
}

void SessionAuthoring::storeSlidersAsNewViseme(const std::string& name) {
    const std::size_t before = core_.document().visemeCount();
    core_.commit("Store sliders as " + name, edit::storeSlidersAsNewViseme(core_.document(), name));
    if (core_.document().visemeCount() > before) {
        core_.selectViseme(name);
        core_.messages().info("Stored the sliders as the new viseme " + quoted(name) + " (preset and mesh)");
    } else {
        core_.messages().info(
            "Stored the sliders as the preset " + quoted(name) +
            (core_.document().visemes
                 ? ": the viseme set is not this face's, generate it from the face to get the mesh"
                 : ": generate the viseme set from the face to get its mesh"));
    }
}

void SessionAuthoring::storeSlidersInViseme(const std::string& name) {
    const auto set = core_.document().visemes;
    core_.commit("Store sliders in " + name, edit::storeSlidersInViseme(core_.document(), name));
    core_.messages().info(set != core_.document().visemes
                              ? "Stored the sliders in " + quoted(name) + ": preset and mesh regenerated"
                              : "Stored the sliders in the preset " + quoted(name) +
                                    " (no mesh of the face)");
}

void SessionAuthoring::removePreset(const std::string& name) {
    core_.commit("Remove preset " + name, edit::removePreset(core_.document(), name));
}

void SessionAuthoring::addAvatarRestViseme(const std::string& requestedName) {
    Document next = edit::addAvatarRestViseme(
        core_.document(), bundledPhonemeFrequencies(assetsDirectory(), "oculus"), requestedName);
    const std::string name = next.avatar.scan->addedRest;
    core_.commit("Add rest viseme " + name, std::move(next));
    core_.selectViseme(name);
}

void SessionAuthoring::setAvatarPattern(const std::string& pattern) {
    if (core_.document().avatar.isSet() && pattern == core_.document().avatar.pattern) return;
    core_.commit(pattern.empty() ? std::string("Viseme targets: Oculus names")
                                 : "Viseme targets '" + pattern + "'",
                 edit::setAvatarPattern(core_.document(), pattern,
                                        bundledPhonemeFrequencies(assetsDirectory(), "oculus")));
    core_.messages().info(std::to_string(core_.document().visemeCount()) + " visemes selected by " +
                          core_.document().avatar.scan->selection);
}

bool SessionAuthoring::visemeSetMadeByFace() {
    const std::uint64_t revision = core_.inputs().revision(kVisemePart | kFacePart);
    if (madeByFace_.revision != revision) {
        const Document& current = core_.document();
        madeByFace_ = {revision, edit::visemeSetMadeByFace(current), edit::visemeFaceParameters(current)};
    }
    return madeByFace_.value;
}

const std::vector<std::vector<double>>& SessionAuthoring::visemeFaceParameters() {
    visemeSetMadeByFace(); // brings the cache up to date
    return madeByFace_.parameters;
}

} // namespace vl::ui
