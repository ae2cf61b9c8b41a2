// Texture images for display: PNG and JPEG decoded, KTX2/WebP reported, absurd sizes refused
// before decoding.
#include "core/io/ImageDecode.h"
#include "core/common/Error.h"
#include "tests/common/TestImages.h"

#include <gtest/gtest.h>

namespace vl {
namespace {

TEST(ImageDecode, PngDecodesToItsPixelsTopRowFirst) {
    const std::vector<std::uint8_t> rgba = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 128, 10, 20, 30, 40};
    const DecodedImage decoded = decodeImage(test::pngBytes(2, 2, rgba), "skin.png", kMaxTextureBytes);
    ASSERT_TRUE(decoded.image) << decoded.problem;
    EXPECT_EQ(decoded.image->width, 2);
    EXPECT_EQ(decoded.image->height, 2);
    EXPECT_EQ(decoded.image->rgba, rgba);
}

TEST(ImageDecode, JpegDecodesNearItsColour) {
    std::vector<std::uint8_t> rgb;
    for (int i = 0; i < 64; ++i) rgb.insert(rgb.end(), {200, 60, 40});
    const DecodedImage decoded = decodeImage(test::jpegBytes(8, 8, rgb), "eye.jpg", kMaxTextureBytes);
    ASSERT_TRUE(decoded.image) << decoded.problem;
    EXPECT_EQ(imageFormatOf(test::jpegBytes(8, 8, rgb)), ImageFormat::Jpeg);
    EXPECT_NEAR(decoded.image->rgba[0], 200, 6);
    EXPECT_NEAR(decoded.image->rgba[1], 60, 6);
    EXPECT_NEAR(decoded.image->rgba[2], 40, 6);
    EXPECT_EQ(decoded.image->rgba[3], 255);
}

TEST(ImageDecode, Ktx2AndWebpAreReportedNotDrawn) {
    const std::string ktx2 = std::string("\xABKTX 20\xBB\r\n\x1a\n", 12) + std::string(64, '\0');
    const DecodedImage a = decodeImage(ktx2, "x", kMaxTextureBytes);
    EXPECT_FALSE(a.image);
    EXPECT_EQ(a.problem, "KTX2 images are not drawn");
    const DecodedImage b = decodeImage(std::string("RIFF\x10\0\0\0WEBPVP8 ", 16), "x", kMaxTextureBytes);
    EXPECT_FALSE(b.image);
    EXPECT_EQ(b.problem, "WebP images are not drawn");
    EXPECT_EQ(decodeImage("GIF89a", "x", kMaxTextureBytes).problem, "neither PNG nor JPEG");
}

TEST(ImageDecode, CorruptDataIsAProblemNotAFailure) {
    const std::string png = test::pngBytes(4, 4, test::solidRgba(4, 4, 9, 9, 9));
    const DecodedImage decoded = decodeImage(png.substr(0, 40), "skin.png", kMaxTextureBytes);
    EXPECT_FALSE(decoded.image);
    EXPECT_NE(decoded.problem.find("corrupt PNG"), std::string::npos) << decoded.problem;
}

TEST(ImageDecode, AbsurdDeclaredSizeIsRefusedNamingTheImage) {
    try {
        decodeImage(test::pngClaiming(65535, 65535), "avatar.glb: images/3", kMaxTextureBytes);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("avatar.glb: images/3: declares 65535 x 65535 pixels"),
                  std::string::npos)
            << e.what();
    }
    // Within the per-image limit but beyond what is left of the mesh's budget.
    EXPECT_THROW(decodeImage(test::pngBytes(2, 2, test::solidRgba(2, 2, 1, 1, 1)), "x", 15), InputError);
    EXPECT_NO_THROW(decodeImage(test::pngBytes(2, 2, test::solidRgba(2, 2, 1, 1, 1)), "x", 16));
}

} // namespace
} // namespace vl
