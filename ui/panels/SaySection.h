#pragma once
// The Reduction panel's Say section: text, voice and rate (document state), Say / Play / Pause, the
// utterance error and the audio status, a typed sequence. The clip plays in SpeechPlayer.
#include "ui/panels/PanelContext.h"

#include <string>

namespace vl::ui {

class SaySection {
  public:
    explicit SaySection(const PanelContext& context) : session_(context.session), speech_(context.speech) {}
    void draw();
    void addProbe(nlohmann::json& summary) const;

  private:
    EditorSession& session_;
    SpeechPlayer& speech_;
    std::string draft_;      // the text box; committed on Say or when the box is left
    std::string syncedText_; // the document's text the draft was last synced with
};

} // namespace vl::ui
