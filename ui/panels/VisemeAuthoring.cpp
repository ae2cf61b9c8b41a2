// Visemes panel, under the list: rename, duplicate, move and delete the selected viseme. A delete
// that would leave phonemes unmapped asks where they go (a popup listing them) instead of failing.
#include "ui/panels/VisemeAuthoring.h"
#include "ui/UiScale.h"

#include "core/common/Error.h"
#include "core/document/PhonemeMapCommands.h"
#include "core/document/VisemeCommands.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>

namespace vl::ui {
namespace {

constexpr const char* kDeletePopup = "Delete viseme";

// "<name> copy", or "<name> copy 2", ... : the first name the document accepts for a new viseme. A
// copy's copy counts on ("aa copy" gives "aa copy 2", not "aa copy copy").
std::string copyName(const Document& document, std::string name) {
    const std::size_t copy = name.rfind(" copy");
    if (copy != std::string::npos && copy > 0) {
        const std::string rest = name.substr(copy + 5);
        const bool numbered =
            rest.size() > 1 && rest[0] == ' ' &&
            std::all_of(rest.begin() + 1, rest.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (rest.empty() || numbered) name.resize(copy);
    }
    for (int k = 1;; ++k) {
        const std::string candidate = name + " copy" + (k == 1 ? "" : " " + std::to_string(k));
        try {
            edit::checkNewVisemeName(document, candidate, "copy");
            return candidate;
        } catch (const InputError&) {
        }
    }
}

} // namespace

void VisemeAuthoring::addProbe(nlohmann::json& summary) const {
    const Document& document = session_.document();
    nlohmann::json presets = nlohmann::json::object();
    if (document.face.cascade)
        for (const VisemeParameters& preset : edit::facePresets(document.face)) {
            nlohmann::json values = nlohmann::json::object();
            for (const auto& [parameter, value] : preset.values) values[parameter] = value;
            presets[preset.name] = std::move(values);
        }
    nlohmann::json parameters = nlohmann::json::object();
    if (document.face.cascade)
        for (std::size_t k = 0; k < document.face.parameters.size(); ++k)
            parameters[document.face.cascade->parameters[k].name] = document.face.parameters[k];
    nlohmann::json phonemes = nlohmann::json::object();
    for (const auto& [phoneme, value] : document.frequencies.phonemes.entries) phonemes[phoneme] = value;
    nlohmann::json map = nlohmann::json::object();
    for (const auto& [phoneme, viseme] : document.frequencies.map.entries) map[phoneme] = viseme;
    nlohmann::json direct = nlohmann::json::object();
    for (const auto& [name, value] : document.frequencies.visemeFrequencies.entries) direct[name] = value;
    // The frequencies the reduction uses, per viseme (empty while they do not resolve).
    nlohmann::json frequencies = nlohmann::json::object();
    const std::vector<std::string> names = visemeNames(document);
    try {
        const std::vector<double> values = documentFrequencies(document);
        for (std::size_t i = 0; i < names.size() && i < values.size(); ++i) frequencies[names[i]] = values[i];
    } catch (const InputError&) {
    }
    summary.update({{"viseme_names", names},
                    {"viseme_frequencies", std::move(frequencies)},
                    {"presets", std::move(presets)},
                    {"parameters", std::move(parameters)},
                    {"phoneme_frequencies", std::move(phonemes)},
                    {"phoneme_based", document.frequencies.isPhonemeBased()},
                    {"phoneme_map", std::move(map)},
                    {"direct_frequencies", std::move(direct)}});
}

void VisemeAuthoring::draw() {
    const VisemeSet* set = session_.visemes();
    const int selected = session_.selectedViseme();
    const bool has = set && selected >= 0 && selected < static_cast<int>(set->size());
    // The field shows the selected viseme's name unless the user is typing a new one.
    if (!editingName_ && (nameFor_ != selected || nameDocument_ != session_.history().revision())) {
        nameFor_ = selected;
        nameDocument_ = session_.history().revision();
        name_ = has ? set->visemes[static_cast<std::size_t>(selected)].name : std::string();
    }
    if (!has) ImGui::BeginDisabled();
    ImGui::SetNextItemWidth(std::min(200.0f, ImGui::GetContentRegionAvail().x * 0.4f));
    const bool entered = ctl::InputTextWithHint("##viseme-name", "select a viseme", &name_,
                                                ImGuiInputTextFlags_EnterReturnsTrue);
    editingName_ = ImGui::IsItemActive();
    ImGui::SameLine();
    if ((ctl::Button("Rename") || entered) && has)
        session_.attempt("Rename", [&] { session_.authoring().renameViseme(selected, name_); });
    ImGui::SameLine();
    if (ctl::Button("Duplicate") && has)
        session_.attempt("Duplicate", [&] {
            const std::string& name = set->visemes[static_cast<std::size_t>(selected)].name;
            session_.authoring().duplicateViseme(selected, copyName(session_.document(), name));
        });
    ImGui::SameLine();
    if (ctl::Button("Delete...") && has) {
        // Phonemes mapped to it need a new viseme: ask. Otherwise delete (Ctrl+Z brings it back).
        if (edit::phonemesMappedTo(session_.document().frequencies,
                                   set->visemes[static_cast<std::size_t>(selected)].name)
                .empty()) {
            session_.attempt("Delete viseme", [&] { session_.authoring().removeViseme(selected); });
        } else {
            openDelete_ = true;
            deleteIndex_ = selected;
            phonemesGoTo_.clear();
        }
    }
    const int last = has ? static_cast<int>(set->size()) - 1 : 0;
    if (has && selected == 0) ImGui::BeginDisabled();
    if (ctl::Button("Move up"))
        session_.attempt("Move viseme", [&] { session_.authoring().moveViseme(selected, selected - 1); });
    if (has && selected == 0) ImGui::EndDisabled();
    ImGui::SameLine();
    if (has && selected == last) ImGui::BeginDisabled();
    if (ctl::Button("Move down"))
        session_.attempt("Move viseme", [&] { session_.authoring().moveViseme(selected, selected + 1); });
    if (has && selected == last) ImGui::EndDisabled();
    if (!has) ImGui::EndDisabled();
    helpMarker("Renames, copies and deletes keep the phoneme map, the frequencies, the constraints and the "
               "face's preset of the viseme in step. Every change is one undo step (Ctrl+Z).");
    deletePopup();
}

void VisemeAuthoring::deletePopup() {
    if (openDelete_) {
        ImGui::OpenPopup(kDeletePopup);
        openDelete_ = false;
    }
    if (!ImGui::BeginPopupModal(kDeletePopup, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const VisemeSet* set = session_.visemes();
    const int index = deleteIndex_;
    if (!set || index < 0 || index >= static_cast<int>(set->size())) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const std::string& name = set->visemes[static_cast<std::size_t>(index)].name;
    const FrequencySource& frequencies = session_.document().frequencies;
    const std::string phonemes = edit::phonemeList(frequencies, edit::phonemesMappedTo(frequencies, name));
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::Text("Phonemes %s map to %s.", phonemes.c_str(), name.c_str());
    ImGui::TextUnformatted("Choose the viseme they map to once it is deleted:");
    ImGui::PopTextWrapPos();
    ImGui::SetNextItemWidth(scaled(200.0f));
    if (ctl::BeginCombo("##phonemes-go-to", phonemesGoTo_.empty() ? "(choose)" : phonemesGoTo_.c_str(),
                        ImGuiComboFlags_HeightLargest)) {
        for (const Viseme& viseme : set->visemes)
            if (viseme.name != name && ctl::Selectable(viseme.name.c_str(), viseme.name == phonemesGoTo_))
                phonemesGoTo_ = viseme.name;
        ImGui::EndCombo();
    }
    const bool chosen = !phonemesGoTo_.empty();
    if (!chosen) ImGui::BeginDisabled();
    if (ctl::Button("Delete and move the phonemes")) {
        session_.attempt("Delete viseme", [&] { session_.authoring().removeViseme(index, phonemesGoTo_); });
        ImGui::CloseCurrentPopup();
    }
    if (!chosen) ImGui::EndDisabled();
    ImGui::SameLine();
    if (ctl::Button("Cancel##delete")) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
}

} // namespace vl::ui
