#include "ui/panels/SpeechPlayer.h"

#include "ui/widgets/SpeechTimeline.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace vl::ui {
namespace {

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

void SpeechPlayer::say(double time, bool pause) {
    if (!session_.attempt("Say", [&] { session_.speech().say(); })) return;
    startAt_ = time;
    startPaused_ = pause;
}

void SpeechPlayer::playSequence(std::string typed, double time) {
    sequence = std::move(typed);
    if (session_.attempt("Playback", [&] { session_.speech().playSequence(sequence, secondsPerKey); }))
        startAt_ = time;
}

void SpeechPlayer::play(double from) {
    const auto& clip = session_.speech().clip();
    if (!clip) return;
    time_ = std::clamp(from, 0.0, clip->duration());
    if (time_ >= clip->duration()) time_ = 0.0; // Play at the end starts again
    playing_ = true;
    shown_ = true;
    if (samples_) audio_.play(samples_, clip->sampleRate, time_);
}

void SpeechPlayer::pause() {
    playing_ = false;
    audio_.stop();
}

void SpeechPlayer::hide() {
    pause();
    shown_ = false;
}

void SpeechPlayer::reset() {
    hide();
    time_ = 0.0;
    clip_ = 0;
    samples_.reset();
}

void SpeechPlayer::advance() {
    const auto& clip = session_.speech().clip();
    if (!clip) return;
    if (clip->id != clip_) { // a new clip: show it from its start (or where a start option says)
        clip_ = clip->id;
        samples_ = clip->samples.empty() ? nullptr
                                         : std::make_shared<const std::vector<std::int16_t>>(clip->samples);
        const double start = startAt_.value_or(0.0);
        startAt_.reset();
        if (std::exchange(startPaused_, false)) {
            pause();
            time_ = std::clamp(start, 0.0, clip->duration());
            shown_ = true;
        } else {
            play(start);
        }
        return;
    }
    if (!playing_) return;
    // The sound is the clock while it plays; otherwise (no device, a typed sequence) the frames.
    if (audio_.playing())
        time_ = audio_.position();
    else
        time_ += ImGui::GetIO().DeltaTime;
    if (time_ >= clip->duration()) {
        if (clip->loops) {
            time_ = std::fmod(time_, clip->duration());
        } else {
            time_ = clip->duration();
            pause();
        }
    }
}

std::vector<float> SpeechPlayer::weights(bool reduced) const {
    const SpeechPlayback* playback = session_.speech().playback();
    if (!playback) return {};
    const std::optional<FaceTrack>& track = reduced ? playback->reduced : playback->full;
    return track ? track->keyWeights(time_) : std::vector<float>{};
}

void SpeechPlayer::timeline(ImVec2 size) {
    const SpeechPlayback* playback = session_.speech().playback();
    if (!playback) return;
    SpeechTimelineData data;
    data.duration = playback->clip->duration();
    data.time = time_;
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
        if (playing_) pause(); // scrubbing holds the playhead where the mouse is
        time_ = *t;
    }
}

nlohmann::json SpeechPlayer::probe() const {
    const SpeechSettings& speech = session_.document().speech;
    nlohmann::json json = {{"text", speech.text},
                           {"voice", speech.voice},
                           {"rate", speech.wordsPerMinute},
                           {"speaking", session_.speech().speaking()},
                           {"time", time_},
                           {"playing", playing_},
                           {"shown", shown()},
                           {"audio", audio_.status()},
                           {"audio_playing", audio_.playing()}};
    const auto& clip = session_.speech().clip();
    if (!clip) return json;
    json["clip"] = clip->label;
    json["clip_id"] = clip->id;
    json["duration"] = clip->duration();
    json["phonemes"] = clip->phonemes.size();
    if (const TimedPhoneme* p = itemAt(clip->phonemes, time_)) json["phoneme"] = p->phoneme;
    const SpeechPlayback* playback = session_.speech().playback();
    json["problem"] = playback->problem;
    if (playback->full) {
        if (const Cue* cue = itemAt(playback->full->cues(), time_)) json["full_cue"] = cue->value;
        json["full_key"] = strongestKey(playback->full->keyWeights(time_), playback->full->model());
    }
    if (playback->reduced) {
        if (const Cue* cue = itemAt(playback->reduced->cues(), time_)) json["reduced_cue"] = cue->value;
        json["reduced_key"] = strongestKey(playback->reduced->keyWeights(time_), playback->reduced->model());
        json["groups"] = playback->groups;
    }
    if (playback->error) {
        const auto& frames = playback->error->frames;
        const auto frame = static_cast<std::size_t>(std::lround(time_ * playback->error->fps));
        json["error_mean"] = playback->error->mean;
        json["error_max"] = playback->error->max;
        json["error_now"] = frames[std::min(frame, frames.size() - 1)];
    }
    return json;
}

} // namespace vl::ui
