#include "ui/session/EditorSession.h"

namespace vl::ui {

EditorSession::EditorSession(SpeechEngines engines)
    : frequencies_(core_, std::move(engines.transcriber)), speech_(core_, std::move(engines.synthesizer)) {}

EditorSession::~EditorSession() {
    reduction_.cancel();
    face_.refinement().wait();
}

void EditorSession::poll() {
    files_.poll();
    speech_.poll();
    frequencies_.poll();
    face_.poll();
    reduction_.poll();
}

void EditorSession::finishBackgroundWork() {
    // poll() may start automatic re-runs; a few rounds settle them.
    for (int round = 0; round < 4; ++round) {
        files_.wait();
        frequencies_.wait();
        speech_.wait();
        face_.refinement().wait();
        reduction_.wait();
        poll();
        if (face_.refinementRunning() || reduction_.running()) continue;
        // A run poll() started may have finished already (running() is false from the worker's last
        // step): one more poll collects it, or starts the next automatic run.
        poll();
        if (!face_.refinementRunning() && !reduction_.running()) break;
    }
}

} // namespace vl::ui
