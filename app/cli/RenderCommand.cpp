// `visemelab render`: a headless preview of one mesh, or a contact sheet of several, as a PNG
// (software rasteriser, no GL).
#include "app/cli/Command.h"
#include "core/common/Error.h"
#include "core/common/TextParsing.h"
#include "core/face/BundledFace.h"
#include "core/io/MeshIO.h"
#include "core/preview/Renderer.h"

#include <cstdio>
#include <filesystem>
#include <string_view>
#include <vector>

namespace vl::cli {

namespace {

struct RenderCliOptions {
    std::vector<std::string> meshes;
    int columns = 4;
    std::string out;
    std::string size = "512x512";
    double yaw = 0.0;
    double pitch = 0.0;
    bool wireframe = false;
    bool faceColours = false;
    std::string focus; // "X,Y,Z,R": frame this sphere instead of each mesh
};

void parseSize(const std::string& text, preview::RenderOptions& options) {
    const auto x = text.find('x');
    if (x == std::string::npos) throwInputError("--size", "expected WxH, e.g. 640x480, got '" + text + "'");
    const auto w = parseInteger(std::string_view(text).substr(0, x), "--size width");
    const auto h = parseInteger(std::string_view(text).substr(x + 1), "--size height");
    if (w < 1 || h < 1 || w > 8192 || h > 8192)
        throwInputError("--size", "width and height must be in 1..8192");
    options.width = static_cast<int>(w);
    options.height = static_cast<int>(h);
}

void parseFocus(const std::string& text, preview::RenderOptions& options) {
    std::vector<double> values;
    std::string_view rest = text;
    while (!rest.empty()) {
        const auto comma = rest.find(',');
        values.push_back(parseFiniteDouble(trim(rest.substr(0, comma)), "--focus"));
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    }
    if (values.size() != 4 || !(values[3] > 0.0))
        throwInputError("--focus", "expected X,Y,Z,R with a radius R > 0, got '" + text + "'");
    options.focusCentre = Vec3(values[0], values[1], values[2]);
    options.focusRadius = values[3];
}

int runRender(const RenderCliOptions& o) {
    if (o.columns < 1) throwInputError("--columns", "must be at least 1");
    preview::RenderOptions options;
    parseSize(o.size, options);
    options.yawDegrees = o.yaw;
    options.pitchDegrees = o.pitch;
    options.wireframe = o.wireframe;
    if (!o.focus.empty()) parseFocus(o.focus, options);
    std::vector<preview::Image> images;
    std::vector<std::string> labels; // file names without extension
    for (const auto& file : o.meshes) {
        labels.push_back(std::filesystem::path(file).stem().string());
        const MeshData mesh = readMesh(file);
        if (o.faceColours) {
            if (!mesh.hasUVs()) throwInputError(file, "--face-colours needs (u,v) coordinates in the mesh");
            options.vertexColours = face::faceColours(mesh.uvs);
        }
        images.push_back(preview::render(mesh, options));
    }
    preview::writePng(o.out,
                      images.size() == 1 ? images.front() : preview::contactSheet(images, o.columns, labels));
    std::fprintf(stderr, "wrote %s\n", o.out.c_str());
    return kExitOk;
}

} // namespace

void addRenderCommand(CLI::App& app, CommandRunner& run) {
    auto options = std::make_shared<RenderCliOptions>();
    auto* cmd = app.add_subcommand("render", "Render meshes to a PNG (headless software renderer)");
    cmd->add_option("meshes", options->meshes, "Mesh files (OBJ, PLY, VRML); several make a contact sheet")
        ->required();
    cmd->add_option("--columns", options->columns, "Images per row of a contact sheet")
        ->capture_default_str();
    cmd->add_option("--out", options->out, "PNG file to write")->required();
    cmd->add_option("--size", options->size, "Image size WxH")->capture_default_str();
    cmd->add_option("--yaw", options->yaw, "Camera turn to the mesh's right (+x), degrees")
        ->capture_default_str();
    cmd->add_option("--pitch", options->pitch, "Camera raise, degrees")->capture_default_str();
    cmd->add_option("--focus", options->focus,
                    "Frame the sphere X,Y,Z,R (mesh units) instead of the whole mesh: a close-up at one "
                    "scale for every mesh");
    cmd->add_flag("--wireframe", options->wireframe, "Overlay the triangle edges");
    cmd->add_flag("--face-colours", options->faceColours,
                  "Colour by (u,v) as the bundled face (lips, eyes, brows)");
    cmd->callback([&run, options] { run = [options] { return runRender(*options); }; });
}

} // namespace vl::cli
