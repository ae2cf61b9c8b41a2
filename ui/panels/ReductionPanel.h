#pragma once
// Reduction panel: target m, the optimal cost for every p with m marked, the model and constraints,
// the groups, the compared viseme and how the right view shows it, and Say.
#include "ui/panels/ConstraintsSection.h"
#include "ui/panels/PanelContext.h"
#include "ui/panels/SaySection.h"

#include <string>

namespace vl::ui {

class ReductionPanel : public SidePanel {
  public:
    explicit ReductionPanel(const PanelContext& context)
        : session_(context.session), speech_(context.speech), constraints_(context), say_(context) {}
    void draw() override;
    void addProbe(nlohmann::json& summary) const override;

    // How the right view shows the merged shape.
    enum class MergedDisplay { ErrorColours, Skin, Overlay };
    MergedDisplay mergedDisplay() const { return mergedDisplay_; }
    // "errors", "skin" or "overlay" (--merged); throws InputError for another name.
    void setMergedDisplay(const std::string& name);
    void setMergedDisplay(MergedDisplay display) { mergedDisplay_ = display; }
    // Millimetres per model unit: the chosen unit, or the guess from the neutral mesh's size.
    double millimetresPerModelUnit() const;

  private:
    nlohmann::json reductionProbe() const; // running, the bound of a branch and bound, the proof, the rest

    EditorSession& session_;
    SpeechPlayer& speech_;
    ConstraintsSection constraints_;
    SaySection say_;
    struct CostView {
        bool logarithmic = true;
        bool percent = false;
        int unit = 0; // 0 auto (guessed from the head size), then m, cm, mm, in
    } costView_;
    MergedDisplay mergedDisplay_ = MergedDisplay::ErrorColours;
};

} // namespace vl::ui
