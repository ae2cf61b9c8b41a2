// GUI smoke test: the editor renders under Xvfb (xvfb-run) and saves a screenshot that shows the
// interface and a face, for several panels. Skips with a message when xvfb-run is not installed.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>

namespace {

bool haveXvfbRun() {
    return std::system("command -v xvfb-run > /dev/null 2>&1") == 0;
}

struct Image {
    int width = 0, height = 0;
    std::unique_ptr<unsigned char, decltype(&stbi_image_free)> pixels{nullptr, &stbi_image_free};
    const unsigned char* at(int x, int y) const {
        return pixels.get() + 3 * (static_cast<std::size_t>(y) * width + x);
    }
};

Image screenshot(const std::string& arguments, const std::string& name, int frames = 4) {
    const auto file = std::filesystem::temp_directory_path() / ("visemelab-editor-" + name + ".png");
    std::filesystem::remove(file);
    const std::string command = "xvfb-run -a -s \"-screen 0 1600x1000x24\" \"" VISEMELAB_EDITOR "\" " +
                                arguments + " --frames " + std::to_string(frames) + " --screenshot \"" +
                                file.string() + "\" > /dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    Image image;
    int channels = 0;
    image.pixels.reset(stbi_load(file.string().c_str(), &image.width, &image.height, &channels, 3));
    EXPECT_NE(image.pixels, nullptr) << file;
    return image;
}

// Fraction of pixels in a rectangle that look like lit skin (bright, red > blue): the face.
double skinFraction(const Image& image, int x0, int y0, int x1, int y1) {
    int skin = 0, total = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++total) {
            const unsigned char* p = image.at(x, y);
            if (p[0] > 120 && p[0] > p[2] + 20) ++skin;
        }
    return total ? static_cast<double>(skin) / total : 0.0;
}

double meanBrightness(const Image& image, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const unsigned char* p = image.at(x, y);
            sum += (p[0] + p[1] + p[2]) / 3.0;
        }
    return sum / ((x1 - x0) * (y1 - y0));
}

// Number of distinct colours (quantised): a black or blank image has one or two.
int distinctColours(const Image& image) {
    std::vector<bool> seen(1 << 15, false);
    int count = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* p = image.at(x, y);
            const int key = (p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3);
            if (!seen[static_cast<std::size_t>(key)]) {
                seen[static_cast<std::size_t>(key)] = true;
                ++count;
            }
        }
    return count;
}

TEST(EditorScreenshot, VisemesPanelShowsTheSampleFace) {
    if (!haveXvfbRun())
        GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth): GUI smoke test skipped";
    const Image image = screenshot("--sample --panel Visemes --viseme aa", "visemes");
    ASSERT_EQ(image.width, 1600);
    ASSERT_EQ(image.height, 1000);
    EXPECT_GT(distinctColours(image), 200);
    // The face fills the middle of the view right of the side panel.
    EXPECT_GT(skinFraction(image, 900, 300, 1300, 700), 0.3);
    // The side panel (left) is a dark interface, not a rendering.
    EXPECT_LT(meanBrightness(image, 0, 100, 300, 900), 90.0);
}

TEST(EditorScreenshot, ReductionPanelShowsBeforeAndAfter) {
    if (!haveXvfbRun())
        GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth): GUI smoke test skipped";
    const Image image = screenshot("--sample --panel Reduction --viseme E", "reduction");
    ASSERT_EQ(image.width, 1600);
    EXPECT_GT(distinctColours(image), 200);
    // Left view: the original viseme; right view: the merged one in error colours (not empty).
    const int side = 576, half = (1600 - side) / 2; // side panel: 36% of the width
    EXPECT_GT(skinFraction(image, side + half / 4, 300, side + 3 * half / 4, 700), 0.3);
    int nonBackground = 0;
    for (int y = 300; y < 700; ++y)
        for (int x = side + half + half / 4; x < side + half + 3 * half / 4; ++x) {
            const unsigned char* p = image.at(x, y);
            if (std::abs(p[0] - 41) + std::abs(p[1] - 43) + std::abs(p[2] - 51) > 40) ++nonBackground;
        }
    EXPECT_GT(nonBackground, 20000);
}

TEST(EditorScreenshot, DeformationPanelShowsTheFace) {
    if (!haveXvfbRun())
        GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth): GUI smoke test skipped";
    const Image image = screenshot("--panel Deformation --preset ou", "deformation");
    EXPECT_GT(skinFraction(image, 900, 300, 1300, 700), 0.3);
}

TEST(EditorScreenshot, LargeRealMeshFolderLoadsAndReduces) {
    if (!haveXvfbRun())
        GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth): GUI smoke test skipped";
    const std::filesystem::path folder = VISEMELAB_SHARED_DATA_DIR "/ict-facekit-mouth";
    if (!std::filesystem::exists(folder / "generic_neutral_mesh.obj"))
        GTEST_SKIP() << folder << " is not available: large-mesh smoke test skipped";
    const Image image =
        screenshot("--visemes \"" + folder.string() + "\" --panel Reduction --viseme mouthPucker", "ict");
    ASSERT_EQ(image.width, 1600);
    const int side = 576, half = (1600 - side) / 2;
    EXPECT_GT(skinFraction(image, side + half / 4, 300, side + 3 * half / 4, 700), 0.3);
    // The merged view is drawn in error colours: mostly blue, with warmer colours around the mouth.
    int blue = 0;
    for (int y = 300; y < 700; ++y)
        for (int x = side + half + half / 4; x < side + half + 3 * half / 4; ++x)
            if (image.at(x, y)[2] > image.at(x, y)[0] + 40) ++blue;
    EXPECT_GT(blue, 20000);
}

TEST(EditorScreenshot, PaintingThroughTheViewChangesTheWeights) {
    if (!haveXvfbRun())
        GTEST_SKIP() << "xvfb-run is not installed (apt-get install xvfb xauth): GUI smoke test skipped";
    // A left-button drag across the face with the subtract brush: the sample's area weights (shown
    // as colours) drop to 0 (blue) along the stroke; away from it they stay as shown before.
    const std::string weights = "--sample --panel Weights --brush subtract";
    const Image before = screenshot(weights, "paint-before", 20);
    const Image after = screenshot(weights + " --drag 950 450 1250 500", "paint-after", 20);
    ASSERT_NE(before.pixels, nullptr);
    ASSERT_NE(after.pixels, nullptr);
    // Pixels whose colour changed visibly between the two pictures.
    auto changed = [&](int x0, int y0, int x1, int y1) {
        int n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) {
                int difference = 0;
                for (int c = 0; c < 3; ++c) difference += std::abs(before.at(x, y)[c] - after.at(x, y)[c]);
                n += difference > 40 ? 1 : 0;
            }
        return n;
    };
    EXPECT_GT(changed(1000, 440, 1200, 510), 2000); // along the stroke
    EXPECT_LT(changed(1000, 200, 1200, 330), 200);  // the forehead is untouched
}

TEST(EditorScreenshot, BadStartOptionFailsWithInvalidInput) {
    if (!haveXvfbRun()) GTEST_SKIP() << "xvfb-run is not installed: GUI smoke test skipped";
    const std::string command = "xvfb-run -a -s \"-screen 0 1600x1000x24\" \"" VISEMELAB_EDITOR
                                "\" --sample --viseme nosuch --screenshot /dev/null 2> /dev/null";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);
}

TEST(EditorScreenshot, NoDisplayGivesAClearMessage) {
    const std::string command = "env -u DISPLAY -u WAYLAND_DISPLAY \"" VISEMELAB_EDITOR
                                "\" --sample 2>&1 | grep -q 'no display: run under xvfb-run'";
    EXPECT_EQ(std::system(command.c_str()), 0);
}

} // namespace
