#pragma once
// The project's file actions, shared by the menus, the shortcuts and the panels: open, save (asking
// for a file when needed), load the sample or a folder, import glTF targets, and the unsaved-changes
// prompt that guards every action that replaces the document.
#include "ui/session/EditorSession.h"
#include "ui/widgets/FileDialog.h"

#include <functional>

namespace vl::ui {

class FileActions {
  public:
    explicit FileActions(EditorSession& session) : session_(session) {}

    // The one file chooser of the editor (a modal: one at a time).
    FileDialog& dialog() { return dialog_; }
    // Runs `action` now, or once the user saved or discarded the unsaved changes.
    void guarded(std::function<void()> action);
    // Saves in the background; asks for a file first when `askForFile` or the project has none.
    // `then` runs once the save has recorded the document (used by the unsaved-changes prompt).
    void saveProject(bool askForFile, std::function<void()> then = {});
    void openProject();
    void loadSample();
    void openVisemeFolder();
    void importGltf(const char* dialogTitle);
    // Quits once nothing is unsaved or the user confirmed (quitConfirmed()).
    void requestQuit();
    bool quitConfirmed() const { return quitConfirmed_; }
    // The file dialog and the unsaved-changes popup, once per frame.
    void draw();

  private:
    void unsavedChangesPopup();

    EditorSession& session_;
    FileDialog dialog_;
    std::function<void()> pendingGuarded_;
    bool openUnsavedPopup_ = false;
    bool quitConfirmed_ = false;
};

} // namespace vl::ui
