#pragma once
// A small modal file chooser (ImGui has none): a folder listing filtered by extension, a name field
// and OK/Cancel. Used for every open, save and import in the editor. Saving onto a file that exists
// asks first ("Replace" or "Cancel"): nothing a designer made is replaced by a slip.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vl::ui {

class FileDialog {
  public:
    enum class Mode { OpenFile, SaveFile, OpenFolder };
    using Accept = std::function<void(const std::filesystem::path&)>;

    // Opens the dialog on the next draw(). `extensions` like {".obj", ".ply"}; empty = all files.
    void open(std::string title, Mode mode, std::vector<std::string> extensions, Accept accept,
              std::string defaultName = {});
    // Draws the modal when open; calls `accept` with the chosen path on OK.
    void draw();
    bool isOpen() const { return visible_; }
    std::filesystem::path folder = std::filesystem::current_path();

  private:
    bool matches(const std::filesystem::path& file) const;
    void finish(std::filesystem::path chosen);
    void drawReplaceQuestion();

    std::string title_;
    Mode mode_ = Mode::OpenFile;
    std::vector<std::string> extensions_;
    Accept accept_;
    std::string name_;
    std::string folderText_;
    bool visible_ = false;
    bool openPending_ = false;
    std::filesystem::path replacing_; // a Save onto this existing file waits for the answer
};

} // namespace vl::ui
