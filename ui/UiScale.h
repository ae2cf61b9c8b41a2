#pragma once
// The window's content scale (HiDPI: 2 on a 2560x1440 laptop screen set to 200 %) as applied to the
// interface: the font is kBaseFontSize times it and ImGui's style sizes are scaled by it
// (EditorApp). Fixed pixel sizes in the layout go through scaled().
namespace vl::ui {

inline constexpr float kBaseFontSize = 15.0f;

// The scale in use: set by EditorApp with the fonts (1 until then).
inline float& uiScaleSetting() {
    static float scale = 1.0f;
    return scale;
}

inline float uiScale() {
    return uiScaleSetting();
}

inline float scaled(float pixels) {
    return pixels * uiScale();
}

} // namespace vl::ui
