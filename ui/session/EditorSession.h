#pragma once
// The editor's session: the document (core/document/Document.h, the one source of truth of what
// the designer edits) in an undo history with its messages (SessionCore), and facets that edit it
// and compute what derives from it, each around one task: files(), frequencies(), weights(),
// face(), reduction(), authoring(), speech(), jobs(). No GL or ImGui: the panels call these, and so
// do the tests. Each edit is a validated command of the core committed as one undo step only when
// it applied, so bad input changes nothing.
#include "core/phonetics/SpeechEngines.h"
#include "ui/session/SessionAuthoring.h"
#include "ui/session/SessionCore.h"
#include "ui/session/SessionFace.h"
#include "ui/session/SessionFiles.h"
#include "ui/session/SessionFrequencies.h"
#include "ui/session/SessionJobs.h"
#include "ui/session/SessionReduction.h"
#include "ui/session/SessionSpeech.h"
#include "ui/session/SessionWeights.h"

#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <string_view>

namespace vl::ui {

class EditorSession {
  public:
    // The speech engines Say and the corpus count use (core/phonetics/SpeechEngines.h); the default
    // argument is evaluated where the session is made, so the session itself constructs none.
    explicit EditorSession(SpeechEngines engines = espeakSpeechEngines());
    ~EditorSession();

    // --- the document and its history (undo, redo, revisions: SessionCore) ---
    const Document& document() const { return core_.document(); }
    const VisemeSet* visemes() const { return document().visemes.get(); }
    std::size_t visemeCount() const { return document().visemeCount(); }
    // The memoized weights, frequencies and per-part revisions of the current document.
    const DocumentInputs& documentInputs() const { return core_.inputs(); }
    SessionCore& history() { return core_; }
    const SessionCore& history() const { return core_; }

    // --- the facets ---
    SessionFiles& files() { return files_; }
    const SessionFiles& files() const { return files_; }
    SessionFrequencies& frequencies() { return frequencies_; }
    SessionWeights& weights() { return weights_; }
    SessionFace& face() { return face_; }
    const SessionFace& face() const { return face_; }
    SessionReduction& reduction() { return reduction_; }
    const SessionReduction& reduction() const { return reduction_; }
    SessionAuthoring& authoring() { return authoring_; }
    SessionSpeech& speech() { return speech_; }
    SessionJobs& jobs() { return jobs_; }

    // --- messages ---
    void info(std::string text) { core_.messages().info(std::move(text)); }
    void error(std::string text) { core_.messages().error(std::move(text)); }
    const std::deque<StatusMessage>& messages() const { return core_.messages().list(); }
    // Runs `action`; an exception becomes an error message "<what>: <reason>" and returns false.
    bool attempt(std::string_view what, const std::function<void()>& action) {
        return core_.messages().attempt(what, action);
    }

    // --- view state (not part of the document, not undoable) ---
    int selectedViseme() const { return core_.selectedViseme(); }
    void selectViseme(int index) { core_.selectViseme(index); }

    // --- frame loop ---
    // Starts a UI frame (SessionCore::beginFrame: references into document() stay valid until the next).
    void beginFrame() { core_.beginFrame(); }
    // Collects finished background work and starts automatic re-runs; call once per frame.
    void poll();
    // Blocks until background work has finished and was collected (tests, screenshots).
    void finishBackgroundWork();

  private:
    SessionCore core_;
    SessionReduction reduction_{core_};
    SessionFiles files_{core_, reduction_};
    SessionFrequencies frequencies_;
    SessionWeights weights_{core_};
    SessionFace face_{core_};
    SessionAuthoring authoring_{core_};
    SessionSpeech speech_;
    SessionJobs jobs_{core_.messages(), files_, face_, reduction_, frequencies_};
};

} // namespace vl::ui
