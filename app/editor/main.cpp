// visemelab-editor: the interactive editor. `--screenshot out.png` renders a few frames and saves
// them instead (used by the GUI smoke test and for the user guide's pictures).
#include "ui/EditorApp.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
    CLI::App app{"VisemeLab editor: viseme reduction and adaptive deformable faces"};
    vl::ui::EditorOptions options;
    // Missing files are not usage errors: the editor opens and shows the error (exit code 3 only
    // with --screenshot).
    app.add_option("--project", options.project, "Open this project file");
    app.add_flag("--sample", options.sample, "Load the bundled sample face and its visemes");
    app.add_option("--visemes", options.visemeFolder, "Load a folder of meshes (one named *neutral*)");
    app.add_option("--avatar", options.avatar, "Import an avatar (glTF, GLB, VRM): its viseme morph targets");
    app.add_option("--targets", options.avatarTargets,
                   "With --avatar: glob selecting the viseme targets (default: the Oculus viseme names)");
    app.add_option("--screenshot", options.screenshot, "Render --frames frames, save this PNG and exit");
    app.add_option("--frames", options.frames, "Frames rendered before the screenshot")
        ->check(CLI::Range(1, 10000));
    app.add_option(
        "--panel", options.panel,
        "Panel to show: Visemes, Frequencies, Weights, Deformation, Refinement, Reduction, Export");
    app.add_option("--viseme", options.viseme, "Viseme to select");
    app.add_option("--preset", options.preset, "Viseme preset applied to the deformable face");
    app.add_option("--screenshot-bits", options.screenshotBits,
                   "Significant bits per colour channel in the screenshot (smaller files)")
        ->check(CLI::Range(1, 8));
    app.add_option("--weights", options.weights, "Weight mode to set once loaded: uniform, area or painted");
    app.add_option("--brush", options.brush, "Paint in the Weights panel: add, subtract or smooth");
    app.add_option("--sculpt", options.sculpt,
                   "Sculpt the selected viseme (Visemes panel): grab, smooth, inflate or deflate");
    app.add_option("--surface", options.surface,
                   "What the views' surfaces show when the document has materials: materials or errors");
    app.add_option(
        "--merged", options.merged,
        "How the Reduction panel shows the merged shape: errors, skin or overlay (on the original)");
    app.add_option("--drag", options.drag, "Left-button drag over the frames: x0 y0 x1 y1 (window pixels)")
        ->expected(4);
    bool noWireframe = false;
    app.add_flag("--no-wireframe", noWireframe, "Start without the wireframe overlay (key W toggles it)");
    app.add_option("--view", options.view, "Standard view at start: front, back, right, left, top, bottom");
    app.add_flag("--orthographic", options.orthographic,
                 "Orthographic projection at start (numpad 5 toggles it)");
    app.add_option("--individual", options.individual, "Base geometry of the face: bundled or retarget");
    app.add_option("--own-face", options.ownFace,
                   "Open Deformation > Use my mesh... on this mesh: its landmarks to confirm");
    app.add_option("--field", options.field, "Deformation field (stage name) to select");
    app.add_option("--play", options.play, "Start the playback at this time in seconds");
    app.add_option("--sequence", options.sequence, "Playback sequence: phonemes or viseme names");
    app.add_option("--say", options.say, "Say this text (Reduction panel) once the project is loaded");
    app.add_option("--say-at", options.sayAt, "Show the speech paused at this time in seconds (screenshots)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--refine", options.refine,
                   "Refine the face with this criterion: depth, normals, contour");
    app.add_option("--map-start", options.mapStart,
                   "Frequencies panel: start a phoneme map from a bundled map (oculus, mpeg4, rhubarb, "
                   "sample-face) or per-phoneme, showing its assignment");
    app.add_option("--probe", options.probe,
                   "GUI tests: write every control's rectangle and a document summary to this JSON "
                   "file after each frame");
    app.add_option(
           "--size",
           [&options](const CLI::results_t& r) {
               return r.size() == 2 && CLI::detail::lexical_cast(r[0], options.width) &&
                      CLI::detail::lexical_cast(r[1], options.height);
           },
           "Window size in pixels (width height)")
        ->expected(2);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    options.wireframe = !noWireframe;
    return vl::ui::runEditor(options);
}
