#pragma once
// The editor program: window, GL context, ImGui and the frame loop; optionally renders a few
// frames and saves a screenshot instead of running interactively.
#include <filesystem>
#include <string>
#include <vector>

namespace vl::ui {

struct EditorOptions {
    std::filesystem::path project;      // open this project at start
    bool sample = false;                // load the bundled sample at start
    std::filesystem::path visemeFolder; // load a folder of meshes at start
    std::filesystem::path avatar;       // import an avatar (glTF, GLB, VRM) at start
    std::string avatarTargets;          // its viseme target pattern (empty: the Oculus names)
    std::filesystem::path screenshot;   // non-empty: render `frames` frames, save a PNG, exit
    int frames = 6;
    int screenshotBits = 8;    // < 8: fewer colour levels, much smaller files
    std::string panel;         // panel to show (Visemes, Frequencies, Weights, ...)
    std::string viseme;        // viseme to select
    std::string individual;    // base geometry of the face: bundled or retarget
    std::string ownFace;       // a mesh whose landmarks the own-face step shows (Use my mesh...)
    std::string preset;        // viseme preset applied to the deformable face
    std::string field;         // deformation field (stage name) to select
    double play = -1.0;        // >= 0: start the playback at this time (seconds)
    std::string sequence;      // playback sequence (phonemes or viseme names)
    std::string say;           // text the Reduction panel's Say speaks at start
    double sayAt = -1.0;       // >= 0: show the speech paused at this time (seconds)
    std::string brush;         // add, subtract or smooth: paint in the Weights panel
    std::string sculpt;        // grab, smooth, inflate or deflate: sculpt in the Visemes panel
    std::string weights;       // uniform, area or painted: the weight mode set after loading
    std::vector<float> drag;   // x0 y0 x1 y1: a left-button drag over the frames (window pixels)
    bool wireframe = true;     // wireframe overlay at start
    std::string view;          // standard view at start: front, back, right, left, top, bottom
    bool orthographic = false; // orthographic projection at start
    std::string surface;  // materials or errors: what the views' surfaces show (documents with materials)
    std::string merged;   // errors, skin or overlay: how the Reduction view shows the merged shape
    std::string refine;   // run a refinement with this criterion (depth, normals, contour)
    std::string mapStart; // open the map editor's assignment from this bundled map id
    std::filesystem::path probe; // GUI tests: write the controls and a document summary here each frame
    int width = 1600;
    int height = 1000;
};

// Returns the process exit code: 0 ok, 1 no display / GL failure, 3 invalid input.
int runEditor(const EditorOptions& options);

// Reads the back buffer (before the swap) and writes it as a PNG, rows flipped to top-down, with
// `bitsPerChannel` significant bits per colour channel.
// Throws std::runtime_error when the file cannot be written.
void saveBackBufferPng(const std::filesystem::path& file, int width, int height, int bitsPerChannel = 8);

} // namespace vl::ui
