// The Reduction panel's model: whether the rest pose is free (a morph-target runtime shows the
// neutral at all weights 0, so the rest viseme and visemes close to the neutral rest at no key) or
// the rest is a key like any other (projects before version 3). One undoable edit each
// (edit::setRest); the core decides which viseme rests.
#include "ui/panels/RestModelSection.h"
#include "ui/UiScale.h"

#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <string>

namespace vl::ui {

void restModelSection(EditorSession& session) {
    const VisemeSet* set = session.visemes();
    if (!set || set->size() < 2) return;
    const Document& document = session.document();
    sectionHeader("Model");
    RestPose pose;
    session.attempt("Rest viseme", [&] { pose = documentRestPose(document); });
    int choice = static_cast<int>(document.rest);
    bool changed = ctl::RadioButton("rest free", &choice, static_cast<int>(RestChoice::Free));
    ImGui::SameLine();
    changed |= ctl::RadioButton("rest is a key", &choice, static_cast<int>(RestChoice::Key));
    ImGui::SameLine();
    changed |= ctl::RadioButton("auto", &choice, static_cast<int>(RestChoice::Auto));
    helpMarker("Rest free: the neutral (all weights 0) costs nothing, so the rest viseme always rests and "
               "another viseme rests when the neutral is closer to it than any key. Rest is a key: every "
               "viseme joins one of the m keys (the model of projects saved before it existed). Auto: "
               "rest free when the set has a rest viseme (sil, viseme_sil or the one chosen here).");
    std::string restViseme = document.restViseme;
    // The rest viseme: sil / viseme_sil by default, or any viseme the designer names.
    const std::string shown =
        restViseme.empty()
            ? (pose.viseme >= 0 ? "default (" + set->visemes[static_cast<std::size_t>(pose.viseme)].name + ")"
                                : std::string("default (none)"))
            : restViseme;
    ImGui::SetNextItemWidth(scaled(180.0f));
    if (ctl::BeginCombo("rest viseme", shown.c_str(), ImGuiComboFlags_HeightLargest)) {
        if (ctl::Selectable("default (sil / viseme_sil)", restViseme.empty())) {
            restViseme.clear();
            changed = true;
        }
        for (const Viseme& viseme : set->visemes)
            if (ctl::Selectable(viseme.name.c_str(), viseme.name == restViseme)) {
                restViseme = viseme.name;
                changed = true;
            }
        ImGui::EndCombo();
    }
    if (pose.free)
        ImGui::TextDisabled(pose.viseme >= 0 ? "Rest free: %s rests (the neutral, all weights 0)"
                                             : "Rest free: the neutral is a free key%s",
                            pose.viseme >= 0
                                ? set->visemes[static_cast<std::size_t>(pose.viseme)].name.c_str()
                                : " (the set has no rest viseme)");
    else
        ImGui::TextDisabled("The rest is a key like any other");
    // A set without a rest viseme gets one: the neutral's shape, so silence maps to the rest pose.
    if (pose.viseme < 0) {
        const bool avatar = document.avatar.isSet();
        if (ctl::Button("Add rest viseme"))
            session.attempt("Add rest viseme", [&] {
                if (avatar)
                    session.authoring().addAvatarRestViseme();
                else
                    session.authoring().addRestViseme(kRestVisemeNames[0]);
            });
        ImGui::SameLine();
        helpMarker(avatar ? "Adds 'viseme_sil' (or 'sil', as the avatar spells its visemes): the base mesh, "
                            "no morph target. Silence maps to it and, with the rest free, it rests (all "
                            "weights 0); the exported avatar gains no target for it."
                          : "Adds 'sil' with the neutral's shape (it rests with the rest free), as the "
                            "Frequencies panel's 'Add rest viseme' does.");
    }
    if (changed)
        session.attempt("Rest model",
                        [&] { session.reduction().setRest(static_cast<RestChoice>(choice), restViseme); });
}

} // namespace vl::ui
