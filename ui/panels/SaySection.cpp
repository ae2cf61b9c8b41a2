// The Reduction panel's Say section: text, voice and rate (document state), Say / Play / Pause, the
// utterance error and the audio status, and a typed sequence of visemes. The clip, its timeline under
// the views and what the GUI probe reports about it are SpeechPlayer's.
#include "ui/panels/SaySection.h"
#include "ui/UiScale.h"

#include "ui/panels/PanelWidgets.h"
#include "ui/panels/SpeechPlayer.h"
#include "ui/widgets/Controls.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace vl::ui {

namespace {

// English espeak-ng voices offered in the combo (any other English voice works from a project).
constexpr const char* kVoices[] = {"en-us", "en-gb", "en-gb-scotland", "en-gb-x-rp", "en-029", "en-us-nyc"};

} // namespace

void SaySection::draw() {
    sectionHeader("Say");
    const SpeechSettings& speech = session_.document().speech;
    // The box edits a draft; the document takes it (one undo step) on Say or when the box is left.
    // An undo or a loaded project changes the document's text: the draft follows.
    if (speech.text != syncedText_) draft_ = syncedText_ = speech.text;
    const auto commitDraft = [&] {
        if (draft_ == speech.text) return true;
        SpeechSettings next = speech;
        next.text = draft_;
        const bool ok = session_.attempt("Say text", [&] { session_.speech().setSettings(next); });
        if (ok) syncedText_ = draft_;
        return ok;
    };
    ctl::InputTextMultiline("##say text", &draft_, ImVec2(-1, 3.4f * ImGui::GetTextLineHeightWithSpacing()));
    if (ImGui::IsItemDeactivatedAfterEdit()) commitDraft();
    if (draft_.empty() && !ImGui::IsItemActive()) {
        const ImVec2 at = ImGui::GetItemRectMin();
        ImGui::GetWindowDrawList()->AddText(ImVec2(at.x + 6, at.y + 4),
                                            ImGui::GetColorU32(ImGuiCol_TextDisabled),
                                            "Type a sentence, then Say");
    }

    ImGui::SetNextItemWidth(scaled(150.0f));
    if (ctl::BeginCombo("voice", speech.voice.c_str())) {
        for (const char* voice : kVoices)
            if (ctl::Selectable(voice, speech.voice == voice)) {
                SpeechSettings next = speech;
                next.voice = voice;
                session_.attempt("Voice", [&] { session_.speech().setSettings(next); });
            }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    int rate = speech.wordsPerMinute;
    ImGui::SetNextItemWidth(scaled(-90.0f));
    if (ctl::SliderInt("words/min", &rate, kMinWordsPerMinute, kMaxWordsPerMinute)) {
        SpeechSettings next = speech;
        next.wordsPerMinute = rate;
        session_.attempt("Speaking rate", [&] { session_.speech().setSettings(next); });
    }
    endEditOnRelease(session_);

    if (ctl::Button("Say", ImVec2(scaled(70), 0)) && commitDraft()) speech_.say();
    const auto& clip = session_.speech().clip();
    ImGui::SameLine();
    if (!clip) ImGui::BeginDisabled();
    if (ctl::Button(speech_.playing() ? "Pause" : "Play", ImVec2(scaled(70), 0))) {
        if (speech_.playing())
            speech_.pause();
        else
            speech_.play(speech_.time());
    }
    ImGui::SameLine();
    if (ctl::Button("Hide", ImVec2(scaled(60), 0))) speech_.hide();
    if (!clip) ImGui::EndDisabled();
    if (session_.speech().speaking()) {
        ImGui::SameLine();
        ImGui::ProgressBar(-1.0f * static_cast<float>(ImGui::GetTime()), ImVec2(-1, 0), "speaking...");
    }
    // Audio is there or it is not; either way the designer knows.
    const std::string& audio = speech_.audio().status();
    ImGui::TextDisabled("%s", audio.empty() ? "audio: the output device is opened by the first Say"
                                            : audio.c_str());

    if (clip) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::Text("Shown: %s", clip->label.c_str());
        ImGui::PopTextWrapPos();
    }
    if (const SpeechPlayback* playback = clip ? session_.speech().playback() : nullptr) {
        if (!playback->problem.empty()) {
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", playback->problem.c_str());
            ImGui::PopTextWrapPos();
        } else if (playback->error) {
            const UtteranceError& e = *playback->error;
            ImGui::Text("Utterance error (m = %d): mean %.3g, max %.3g at %.2f s", playback->groups, e.mean,
                        e.max, e.maxTime);
            ImGui::SameLine();
            helpMarker(
                "The weighted squared distance between the mouth driven by the full set and by the reduced "
                "set, frame by frame (60 fps) while the clip plays; mean over time and worst frame. "
                "Plotted under the timeline. No frequencies: the speech itself weights the visemes.");
            ImGui::Text("%.2f %% of the mouth's motion is lost on this clip", 100.0 * e.relative);
            if (const auto& d = playback->displacement) {
                ImGui::Text("Speech error: RMS %.3g %s, max %.3g %s at %.2f s", d->rms, d->unit.c_str(),
                            d->max, d->unit.c_str(), d->maxTime);
                ImGui::SameLine();
                helpMarker(
                    "How far the reduced mouth's vertices are from the full mouth's (the vertices of "
                    "nonzero weight), root mean square over vertices and time, and the largest distance "
                    "of any vertex in any frame. Avatars are in metres (glTF): shown in mm.");
            }
        } else {
            ImGui::TextDisabled("Utterance error: waiting for the reduction");
        }
    }

    if (ctl::TreeNode("Typed sequence")) {
        ImGui::SetNextItemWidth(-1);
        ctl::InputTextWithHint("##sequence", "phonemes or visemes, e.g. PP aa E RR (empty: all visemes)",
                               &speech_.sequence);
        ImGui::SetNextItemWidth(scaled(160.0f));
        ctl::SliderFloat("s per key", &speech_.secondsPerKey, 0.05f, 1.0f, "%.2f s");
        ImGui::SameLine();
        if (ctl::Button("Play sequence")) speech_.playSequence(speech_.sequence);
        ImGui::TreePop();
    }
}

void SaySection::addProbe(nlohmann::json& summary) const {
    nlohmann::json say = speech_.probe();
    say["draft"] = draft_;
    summary["say"] = std::move(say);
    summary["playing"] = speech_.playing();
}

} // namespace vl::ui
