#pragma once
// The session's authoring facet: the viseme set's edits (import, remove, rename, duplicate, move,
// blend, sculpt, rest visemes, the avatar's target pattern) and the face's presets stored from the
// sliders, each a validated command of the core (core/document/VisemeCommands.h) committed as one
// undo step; the selection follows the viseme it names.
#include "core/document/Document.h"
#include "core/paint/SculptBrush.h"
#include "ui/session/SessionCore.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace vl::ui {

class SessionAuthoring {
  public:
    explicit SessionAuthoring(SessionCore& core) : core_(core) {}

    // Adds one viseme mesh; throws the core's interpolability error and changes nothing on failure.
    void importViseme(const std::string& name, const std::filesystem::path& file);
    // Phonemes mapped to the viseme go to `phonemesGoTo`; without one such a removal is refused.
    void removeViseme(int index, const std::string& phonemesGoTo = {});
    void renameViseme(int index, const std::string& name);
    void duplicateViseme(int index, const std::string& name);
    void moveViseme(int from, int to);
    void addRestViseme(const std::string& name);
    // A sculpt stroke's shape of viseme `index` (edit::setVisemeShape): the calls of one stroke merge
    // into one undo step named after the tool; endEdit() at the stroke's end closes it.
    void sculptViseme(int index, std::vector<Vec3> positions, SculptTool tool);
    // A new viseme mixed from others (edit::addBlendedViseme); it becomes the selection.
    void addBlendedViseme(const std::string& name, const std::vector<std::pair<int, double>>& mix);
    // An avatar's rest viseme (edit::addAvatarRestViseme, with the bundled Oculus table).
    // `name`: one of kRestVisemeNames; empty: the one the avatar's naming suggests.
    void addAvatarRestViseme(const std::string& name = {});
    // Another target pattern for the avatar's visemes (one undo step; refused when < 2 visemes).
    void setAvatarPattern(const std::string& pattern);
    // The sliders as a new viseme / into an existing one (preset, and mesh when the set is the face's).
    void storeSlidersAsNewViseme(const std::string& name);
    void storeSlidersInViseme(const std::string& name);
    void removePreset(const std::string& name);
    // True when the viseme set is the face's own (memoized per revision of the set and the face).
    bool visemeSetMadeByFace();
    // For such a set, each viseme's face parameter vector (edit::visemeFaceParameters; memoized):
    // the viseme view poses the head's parts with it. Empty otherwise.
    const std::vector<std::vector<double>>& visemeFaceParameters();

  private:
    SessionCore& core_;
    // visemeSetMadeByFace() cache: the answer and the visemes' parameter vectors at `revision`
    // (of the viseme set and the face; 0: none yet).
    struct MadeByFace {
        std::uint64_t revision = 0;
        bool value = false;
        std::vector<std::vector<double>> parameters;
    } madeByFace_;
};

} // namespace vl::ui
