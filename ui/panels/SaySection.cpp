// The Reduction panel's Say section: text, voice and rate (document state), Say / Play / Pause, the
// utterance error and the audio status; a typed sequence of visemes; the timeline under the views
// and what the GUI probe reports about speech. The clip is played by EditorUi::advanceSpeech.
#include "ui/EditorUi.h"
#include "ui/panels/PanelWidgets.h"
#include "ui/widgets/Controls.h"
#include "ui/widgets/SpeechTimeline.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace vl::ui {

namespace {

// English espeak-ng voices offered in the combo (any other English voice works from a project).
constexpr const char* kVoices[] = {"en-us", "en-gb", "en-gb-scotland", "en-gb-x-rp", "en-029", "en-us-nyc"};

// The item of `items` (contiguous, from 0) playing at `t`.
template <class Item> const Item* itemAt(const std::vector<Item>& items, double t) {
    const auto it = std::upper_bound(items.begin(), items.end(), t,
                                     [](double time, const Item& item) { return time < item.end; });
    return it == items.end() ? (items.empty() ? nullptr : &items.back()) : &*it;
}

// Name of the key with the largest weight in `weights` ("neutral" when all are small).
std::string strongestKey(const std::vector<float>& weights, const ReducedModel& model) {
    const auto it = std::max_element(weights.begin(), weights.end());
    if (it == weights.end() || *it < 0.5f) return "neutral";
    return model.keys[static_cast<std::size_t>(it - weights.begin())].name;
}

} // namespace

void EditorUi::saySection() {
    sectionHeader("Say");
    const SpeechSettings& speech = session.document().speech;
    // The box edits a draft; the document takes it (one undo step) on Say or when the box is left.
    // An undo or a loaded project changes the document's text: the draft follows.
    if (speech.text != say_.syncedText) say_.draft = say_.syncedText = speech.text;
    const auto commitDraft = [&] {
        if (say_.draft == speech.text) return true;
        SpeechSettings next = speech;
        next.text = say_.draft;
        const bool ok = session.attempt("Say text", [&] { session.setSpeech(next); });
        if (ok) say_.syncedText = say_.draft;
        return ok;
    };
    ctl::InputTextMultiline("##say text", &say_.draft,
                            ImVec2(-1, 3.4f * ImGui::GetTextLineHeightWithSpacing()));
    if (ImGui::IsItemDeactivatedAfterEdit()) commitDraft();
    if (say_.draft.empty() && !ImGui::IsItemActive()) {
        const ImVec2 at = ImGui::GetItemRectMin();
        ImGui::GetWindowDrawList()->AddText(ImVec2(at.x + 6, at.y + 4),
                                            ImGui::GetColorU32(ImGuiCol_TextDisabled),
                                            "Type a sentence, then Say");
    }

    ImGui::SetNextItemWidth(150);
    if (ctl::BeginCombo("voice", speech.voice.c_str())) {
        for (const char* voice : kVoices)
            if (ctl::Selectable(voice, speech.voice == voice)) {
                SpeechSettings next = speech;
                next.voice = voice;
                session.attempt("Voice", [&] { session.setSpeech(next); });
            }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    int rate = speech.wordsPerMinute;
    ImGui::SetNextItemWidth(-90);
    if (ctl::SliderInt("words/min", &rate, kMinWordsPerMinute, kMaxWordsPerMinute)) {
        SpeechSettings next = speech;
        next.wordsPerMinute = rate;
        session.attempt("Speaking rate", [&] { session.setSpeech(next); });
    }
    endEditOnRelease(session);

    if (ctl::Button("Say", ImVec2(70, 0)) && commitDraft()) startSay();
    const auto& clip = session.speechClip();
    ImGui::SameLine();
    if (!clip) ImGui::BeginDisabled();
    if (ctl::Button(say_.playing ? "Pause" : "Play", ImVec2(70, 0))) {
        if (say_.playing)
            pauseSpeech();
        else
            playSpeech(say_.time);
    }
    ImGui::SameLine();
    if (ctl::Button("Hide", ImVec2(60, 0))) {
        pauseSpeech();
        say_.shown = false;
    }
    if (!clip) ImGui::EndDisabled();
    if (session.speaking()) {
        ImGui::SameLine();
        ImGui::ProgressBar(-1.0f * static_cast<float>(ImGui::GetTime()), ImVec2(-1, 0), "speaking...");
    }
    // Audio is there or it is not; either way the designer knows.
    const std::string& audio = audio_.status();
    ImGui::TextDisabled("%s", audio.empty() ? "audio: the output device is opened by the first Say"
                                            : audio.c_str());

    if (clip) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::Text("Shown: %s", clip->label.c_str());
        ImGui::PopTextWrapPos();
    }
    if (const SpeechPlayback* playback = clip ? session.speechPlayback() : nullptr) {
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
                               &say_.sequence);
        ImGui::SetNextItemWidth(160);
        ctl::SliderFloat("s per key", &say_.secondsPerKey, 0.05f, 1.0f, "%.2f");
        ImGui::SameLine();
        if (ctl::Button("Play sequence"))
            session.attempt("Playback", [&] { session.playSequence(say_.sequence, say_.secondsPerKey); });
        ImGui::TreePop();
    }
}

void EditorUi::sayTimeline(ImVec2 size) {
    const SpeechPlayback* playback = session.speechPlayback();
    if (!playback) return;
    SpeechTimelineData data;
    data.duration = playback->clip->duration();
    data.time = say_.time;
    data.phonemes = playback->clip->phonemes;
    if (playback->full) data.fullCues = playback->full->cues();
    if (playback->reduced) {
        data.reducedCues = playback->reduced->cues();
        data.reducedName = "m = " + std::to_string(playback->groups);
        // Rest-free: phonemes of resting visemes show the neutral, besides the m keys.
        if (!playback->reduced->model().resting.empty()) data.reducedName += " + rest";
    }
    if (playback->error) {
        data.error = playback->error->frames;
        data.errorFps = playback->error->fps;
        data.errorMean = playback->error->mean;
    }
    if (const auto t = speechTimeline("##say timeline", data, size)) {
        if (say_.playing) pauseSpeech(); // scrubbing holds the playhead where the mouse is
        say_.time = *t;
    }
}

nlohmann::json EditorUi::sayProbe() {
    const SpeechSettings& speech = session.document().speech;
    nlohmann::json json = {{"text", speech.text},
                           {"voice", speech.voice},
                           {"rate", speech.wordsPerMinute},
                           {"draft", say_.draft},
                           {"speaking", session.speaking()},
                           {"time", say_.time},
                           {"playing", say_.playing},
                           {"shown", speechShown()},
                           {"audio", audio_.status()},
                           {"audio_playing", audio_.playing()}};
    const auto& clip = session.speechClip();
    if (!clip) return json;
    json["clip"] = clip->label;
    json["clip_id"] = clip->id;
    json["duration"] = clip->duration();
    json["phonemes"] = clip->phonemes.size();
    if (const TimedPhoneme* p = itemAt(clip->phonemes, say_.time)) json["phoneme"] = p->phoneme;
    const SpeechPlayback* playback = session.speechPlayback();
    json["problem"] = playback->problem;
    if (playback->full) {
        if (const Cue* cue = itemAt(playback->full->cues(), say_.time)) json["full_cue"] = cue->value;
        json["full_key"] = strongestKey(playback->full->keyWeights(say_.time), playback->full->model());
    }
    if (playback->reduced) {
        if (const Cue* cue = itemAt(playback->reduced->cues(), say_.time)) json["reduced_cue"] = cue->value;
        json["reduced_key"] =
            strongestKey(playback->reduced->keyWeights(say_.time), playback->reduced->model());
        json["groups"] = playback->groups;
    }
    if (playback->error) {
        const auto& frames = playback->error->frames;
        const auto frame = static_cast<std::size_t>(std::lround(say_.time * playback->error->fps));
        json["error_mean"] = playback->error->mean;
        json["error_max"] = playback->error->max;
        json["error_now"] = frames[std::min(frame, frames.size() - 1)];
    }
    return json;
}

} // namespace vl::ui
