#pragma once
// What every panel is given by reference: the session it edits, the project's file actions (the
// file dialog, the unsaved-changes guard) and the speech clip's player, which the views share.
#include <nlohmann/json.hpp>

namespace vl::ui {

class EditorSession;
class FileActions;
class SpeechPlayer;

struct PanelContext {
    EditorSession& session;
    FileActions& files;
    SpeechPlayer& speech;
};

// A tab of the side panel: draws its controls and adds what the GUI tests check of it to the
// probe's summary.
class SidePanel {
  public:
    virtual ~SidePanel() = default;
    virtual void draw() = 0;
    virtual void addProbe(nlohmann::json& /*summary*/) const {}
    // The document was replaced (SessionCore::documentEpoch): drop what showed the old one.
    virtual void documentReplaced() {}
};

} // namespace vl::ui
