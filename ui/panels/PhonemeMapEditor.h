#pragma once
// The Frequencies panel's phoneme -> viseme map: start a map (bundled, a file, one viseme per
// phoneme) and assign its visemes to the set's, then edit it phoneme by phoneme and viseme by viseme.
#include "core/document/PhonemeMapCommands.h"
#include "ui/panels/PanelContext.h"

#include <string>
#include <vector>

namespace vl::ui {

class PhonemeMapEditor {
  public:
    explicit PhonemeMapEditor(const PanelContext& context)
        : session_(context.session), files_(context.files) {}

    // "Start a map from...", Save map, Use direct frequencies, and the assignment while one is open.
    void startSection();
    // One row per phoneme (frequency, share, viseme), one per viseme (its phonemes, move them all).
    void editor();
    // Opens the assignment from a bundled map id ("oculus", ...) or "per-phoneme"; throws InputError.
    void startFrom(const std::string& id);
    bool assigning() const { return mapStart_.open; }
    void addProbe(nlohmann::json& summary) const;

  private:
    void openMapStart(std::string title, const PhonemeVisemeMap& map);
    void restVisemeRow(); // a viseme with the neutral's shape, e.g. "sil" for the pause

    EditorSession& session_;
    FileActions& files_;
    std::string restName_ = "sil"; // name of a rest viseme to add
    struct MapStartView {
        bool open = false;
        std::string title; // the map it starts from, for the panel and the undo step
        FrequencyTable table;
        PhonemeVisemeMap map;
        std::vector<edit::MapAssignment> rows;
    } mapStart_;
};

} // namespace vl::ui
