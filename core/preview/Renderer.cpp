#include "core/preview/Renderer.h"

#include "core/common/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace vl::preview {

namespace {

// Pixels are rendered at this factor and averaged down: cheap anti-aliasing of edges and wires.
constexpr int kSupersample = 2;

struct Camera {
    Vec3 eye, right, up, forward;
    double focal; // pixels per unit of tan(angle)
    double cx, cy;

    // Screen position (x right, y down) and view depth (> 0 in front of the camera).
    Vec3 project(const Vec3& p) const {
        const Vec3 d = p - eye;
        const double z = OpenMesh::dot(d, forward);
        return Vec3(cx + focal * OpenMesh::dot(d, right) / z, cy - focal * OpenMesh::dot(d, up) / z, z);
    }
};

Camera makeCamera(const MeshData& mesh, const RenderOptions& o, int width, int height) {
    Vec3 lo, hi;
    bounds(mesh.positions, lo, hi);
    const bool focused = o.focusRadius > 0.0;
    const Vec3 centre = focused ? o.focusCentre : (lo + hi) * 0.5;
    const double radius = focused ? o.focusRadius : std::max((hi - lo).norm() * 0.5, 1e-9);
    const double yaw = o.yawDegrees * M_PI / 180.0;
    const double pitch = o.pitchDegrees * M_PI / 180.0;
    const double halfFov = 0.5 * o.fovDegrees * M_PI / 180.0;
    const Vec3 towardEye(std::sin(yaw) * std::cos(pitch), std::sin(pitch), std::cos(yaw) * std::cos(pitch));
    Camera c;
    c.eye = centre + towardEye * (radius / std::sin(halfFov));
    c.forward = -towardEye;
    const Vec3 worldUp = std::abs(towardEye[1]) > 0.99 ? Vec3(0, 0, -1) : Vec3(0, 1, 0);
    c.right = OpenMesh::cross(c.forward, worldUp).normalized();
    c.up = OpenMesh::cross(c.right, c.forward);
    c.cx = 0.5 * width;
    c.cy = 0.5 * height;
    if (focused) { // the focus sphere fills the image's shorter side
        c.focal = 0.5 * std::min(width, height) / std::tan(halfFov);
        return c;
    }
    // Zoom so the projected mesh fills the image with a small margin.
    double extentX = 1e-12, extentY = 1e-12;
    for (const auto& p : mesh.positions) {
        const Vec3 d = p - c.eye;
        const double z = std::max(OpenMesh::dot(d, c.forward), 1e-9);
        extentX = std::max(extentX, std::abs(OpenMesh::dot(d, c.right)) / z);
        extentY = std::max(extentY, std::abs(OpenMesh::dot(d, c.up)) / z);
    }
    c.focal = 0.92 * std::min(0.5 * width / extentX, 0.5 * height / extentY);
    return c;
}

// Distance in pixels from point (x,y) to the line through a and b.
double lineDistance(double x, double y, const Vec3& a, const Vec3& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double len = std::hypot(dx, dy);
    if (len == 0.0) return std::hypot(x - a[0], y - a[1]);
    return std::abs((x - a[0]) * dy - (y - a[1]) * dx) / len;
}

struct Target {
    int width, height;
    std::vector<double> depth; // 1/z, larger is nearer
    std::vector<Vec3> colour;
};

void rasterise(Target& t, const Camera& cam, const std::array<Vec3, 3>& world,
               const std::array<Vec3, 3>& normal, const std::array<Vec3, 3>& albedo, const RenderOptions& o,
               double wireWidth) {
    std::array<Vec3, 3> s;
    for (int k = 0; k < 3; ++k) {
        s[k] = cam.project(world[k]);
        if (s[k][2] <= 1e-9) return; // behind the camera
    }
    const double area = (s[1][0] - s[0][0]) * (s[2][1] - s[0][1]) - (s[2][0] - s[0][0]) * (s[1][1] - s[0][1]);
    if (area == 0.0) return;
    const int x0 = std::max(0, static_cast<int>(std::floor(std::min({s[0][0], s[1][0], s[2][0]}))));
    const int x1 = std::min(t.width - 1, static_cast<int>(std::ceil(std::max({s[0][0], s[1][0], s[2][0]}))));
    const int y0 = std::max(0, static_cast<int>(std::floor(std::min({s[0][1], s[1][1], s[2][1]}))));
    const int y1 = std::min(t.height - 1, static_cast<int>(std::ceil(std::max({s[0][1], s[1][1], s[2][1]}))));
    const Vec3 light = (cam.right * -0.35 + cam.up * 0.45 - cam.forward).normalized();
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            double b[3];
            for (int k = 0; k < 3; ++k) {
                const Vec3& p = s[(k + 1) % 3];
                const Vec3& q = s[(k + 2) % 3];
                b[k] = ((q[0] - p[0]) * (py - p[1]) - (px - p[0]) * (q[1] - p[1])) / area;
            }
            if (b[0] < 0.0 || b[1] < 0.0 || b[2] < 0.0) continue;
            // Perspective-correct weights from the screen barycentrics.
            const double invZ = b[0] / s[0][2] + b[1] / s[1][2] + b[2] / s[2][2];
            const std::size_t pixel = static_cast<std::size_t>(y) * t.width + x;
            if (invZ <= t.depth[pixel]) continue;
            t.depth[pixel] = invZ;
            Vec3 n(0, 0, 0), a(0, 0, 0);
            for (int k = 0; k < 3; ++k) {
                const double w = b[k] / s[k][2] / invZ;
                n += normal[k] * w;
                a += albedo[k] * w;
            }
            if (n.norm() > 0.0) n.normalize();
            double lambert = OpenMesh::dot(n, light);
            if (OpenMesh::dot(n, cam.forward) > 0.0) lambert = 0.3 * std::abs(lambert); // back face: dim
            Vec3 c = a * (0.22 + 0.78 * std::max(0.0, lambert));
            if (o.wireframe) {
                double d = std::numeric_limits<double>::max();
                for (int k = 0; k < 3; ++k) d = std::min(d, lineDistance(px, py, s[k], s[(k + 1) % 3]));
                if (d < wireWidth) c = o.wireColour;
            }
            t.colour[pixel] = c;
        }
    }
}

std::uint8_t toByte(double v) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

} // namespace

Image render(const MeshData& mesh, const RenderOptions& options) {
    if (mesh.positions.empty() || mesh.triangles.empty()) throwInputError("render", "the mesh is empty");
    if (options.width < 1 || options.height < 1 || options.width > 8192 || options.height > 8192)
        throwInputError("render", "image size " + std::to_string(options.width) + "x" +
                                      std::to_string(options.height) + " is outside 1..8192");
    if (!options.vertexColours.empty() && options.vertexColours.size() != mesh.positions.size())
        throwInputError("render", "got " + std::to_string(options.vertexColours.size()) +
                                      " vertex colours for " + std::to_string(mesh.positions.size()) +
                                      " vertices");
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
        for (const auto v : mesh.triangles[f])
            if (v >= mesh.positions.size())
                throwInputError("render",
                                "triangle " + std::to_string(f) + " has a vertex index out of range");

    Target t;
    t.width = options.width * kSupersample;
    t.height = options.height * kSupersample;
    t.depth.assign(static_cast<std::size_t>(t.width) * t.height, 0.0);
    t.colour.assign(t.depth.size(), options.background);
    const Camera cam = makeCamera(mesh, options, t.width, t.height);
    const auto normals = vertexNormals(mesh.positions, mesh.triangles);
    const Vec3 skin(0.78, 0.74, 0.70);
    for (const auto& tri : mesh.triangles) {
        std::array<Vec3, 3> p, n, a;
        for (int k = 0; k < 3; ++k) {
            p[k] = mesh.positions[tri[k]];
            n[k] = normals[tri[k]];
            a[k] = options.vertexColours.empty() ? skin : options.vertexColours[tri[k]];
        }
        rasterise(t, cam, p, n, a, options, 0.6 * kSupersample);
    }

    Image image;
    image.width = options.width;
    image.height = options.height;
    image.rgba.resize(static_cast<std::size_t>(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            Vec3 sum(0, 0, 0);
            for (int sy = 0; sy < kSupersample; ++sy)
                for (int sx = 0; sx < kSupersample; ++sx)
                    sum += t.colour[static_cast<std::size_t>(y * kSupersample + sy) * t.width +
                                    x * kSupersample + sx];
            sum /= double(kSupersample * kSupersample);
            std::uint8_t* px = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
            for (int k = 0; k < 3; ++k) px[k] = toByte(sum[k]);
            px[3] = 255;
        }
    return image;
}

Image contactSheet(const std::vector<Image>& images, int columns, const std::vector<std::string>& labels) {
    if (images.empty() || columns < 1)
        throwInputError("contact sheet", "needs at least one image and column");
    if (!labels.empty() && labels.size() != images.size())
        throwInputError("contact sheet", "got " + std::to_string(labels.size()) + " labels for " +
                                             std::to_string(images.size()) + " images");
    const int w = images.front().width, h = images.front().height;
    for (const auto& im : images)
        if (im.width != w || im.height != h) throwInputError("contact sheet", "images differ in size");
    const int n = static_cast<int>(images.size());
    const int cols = std::min(columns, n);
    const int rows = (n + cols - 1) / cols;
    Image sheet;
    sheet.width = w * cols;
    sheet.height = h * rows;
    sheet.rgba.assign(static_cast<std::size_t>(sheet.width) * sheet.height * 4, 0);
    for (int k = 0; k < n; ++k) {
        const int ox = (k % cols) * w, oy = (k / cols) * h;
        for (int y = 0; y < h; ++y)
            std::copy_n(&images[k].rgba[static_cast<std::size_t>(y) * w * 4], static_cast<std::size_t>(w) * 4,
                        &sheet.rgba[(static_cast<std::size_t>(oy + y) * sheet.width + ox) * 4]);
        if (!labels.empty())
            drawLabel(sheet, ox + 6, oy + 6, labels[k], std::max(1, h / 100), Vec3(0.9, 0.9, 0.9));
    }
    return sheet;
}

} // namespace vl::preview
