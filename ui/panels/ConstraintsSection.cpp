// The Reduction panel's constraints: visemes pinned as their own key (PP, so the lips close for p, b,
// m), pairs kept apart, pairs kept together. Every change is one undoable edit of the document; the
// core checks it (known names, no contradiction) and the reduction honours it exactly.
#include "ui/panels/ConstraintsSection.h"
#include "ui/UiScale.h"

#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace vl::ui {
namespace {

// A combo over the viseme names; true when the choice changed.
bool visemeCombo(const char* label, const VisemeSet& set, int& choice) {
    choice = std::clamp(choice, 0, static_cast<int>(set.size()) - 1);
    bool changed = false;
    // Every viseme visible at once (up to the screen's height), not an 8-row scrolled list.
    if (ctl::BeginCombo(label, set.visemes[static_cast<std::size_t>(choice)].name.c_str(),
                        ImGuiComboFlags_HeightLargest)) {
        for (int i = 0; i < static_cast<int>(set.size()); ++i)
            if (ctl::Selectable(set.visemes[static_cast<std::size_t>(i)].name.c_str(), i == choice)) {
                choice = i;
                changed = true;
            }
        ImGui::EndCombo();
    }
    return changed;
}

} // namespace

void ConstraintsSection::draw() {
    const VisemeSet* set = session_.visemes();
    if (!set || set->size() < 2) return;
    sectionHeader("Constraints");
    ConstraintNames constraints = session_.document().constraints;
    bool changed = false;
    const auto nameOf = [&](int i) { return set->visemes[static_cast<std::size_t>(i)].name; };

    ImGui::SetNextItemWidth(scaled(110.0f));
    visemeCombo("##pinned viseme", *set, pin_);
    ImGui::SameLine();
    if (ctl::Button("Pin as its own key")) {
        const std::string name = nameOf(pin_);
        if (std::find(constraints.pinned.begin(), constraints.pinned.end(), name) ==
            constraints.pinned.end()) {
            constraints.pinned.push_back(name);
            changed = true;
        }
    }
    helpMarker("A pinned viseme is never merged with another (e.g. PP, so the lips close for p, b, m).");

    ImGui::SetNextItemWidth(scaled(110.0f));
    visemeCombo("##first of pair", *set, first_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(scaled(110.0f));
    visemeCombo("##second of pair", *set, second_);
    ImGui::SameLine();
    const std::pair<std::string, std::string> pair{nameOf(first_), nameOf(second_)};
    if (ctl::Button("Keep apart")) {
        constraints.apart.push_back(pair);
        changed = true;
    }
    ImGui::SameLine();
    if (ctl::Button("Keep together")) {
        constraints.together.push_back(pair);
        changed = true;
    }

    // The constraints in force, each with a button that removes it.
    int id = 0;
    const auto removable = [&](const std::string& text) {
        ImGui::PushID(id++);
        const bool remove = ctl::SmallButton("x");
        ImGui::PopID();
        ImGui::SameLine();
        ImGui::TextWrapped("%s", text.c_str());
        probe::recordArea(text.c_str(), "text");
        return remove;
    };
    for (std::size_t i = 0; i < constraints.pinned.size(); ++i)
        if (removable("pinned: " + constraints.pinned[i])) {
            constraints.pinned.erase(constraints.pinned.begin() + static_cast<std::ptrdiff_t>(i));
            changed = true;
            break;
        }
    for (std::size_t i = 0; i < constraints.apart.size(); ++i)
        if (removable("apart: " + constraints.apart[i].first + " / " + constraints.apart[i].second)) {
            constraints.apart.erase(constraints.apart.begin() + static_cast<std::ptrdiff_t>(i));
            changed = true;
            break;
        }
    for (std::size_t i = 0; i < constraints.together.size(); ++i)
        if (removable("together: " + constraints.together[i].first + " + " +
                      constraints.together[i].second)) {
            constraints.together.erase(constraints.together.begin() + static_cast<std::ptrdiff_t>(i));
            changed = true;
            break;
        }
    if (constraints.empty()) ImGui::TextDisabled("No constraints: the optimum over all groupings.");
    if (changed)
        session_.attempt("Constraints", [&] { session_.reduction().setConstraints(std::move(constraints)); });
}

} // namespace vl::ui
