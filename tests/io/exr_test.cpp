// EXR: exact float round trips of RGB and of the depth and normal layers,
// the channel names other tools expect (Z, N.x, N.y, N.z), and clear errors
// for malformed images and data.
#include "zeroset/io/exr.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <stdexcept>
#include <string>

#include "support/temp_dir.hpp"
#include "zeroset/io/image_reader.hpp"
#include "zeroset/io/image_writer.hpp"

namespace zeroset {
namespace {

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

Image ramp(int width, int height) {
    Image image(width, height);
    float v = -1.5f;
    for (Vec3f& p : image.pixels) {
        p = {v, v * 2.25f, 1.0f / (v + 9.0f)};
        v += 0.173f;
    }
    return image;
}

TEST(Exr, RgbRoundTripIsExactAndHasNoLayers) {
    Image image = ramp(5, 3);
    image.at(4, 2) = {std::numeric_limits<float>::infinity(), 1e30f, std::numeric_limits<float>::denorm_min()};
    const Image decoded = decode_exr(encode_exr(image));
    ASSERT_EQ(decoded.width, 5);
    ASSERT_EQ(decoded.height, 3);
    EXPECT_FALSE(decoded.has_layers());
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(same_bits(decoded.pixels[i][c], image.pixels[i][c])) << i << " " << c;
}

TEST(Exr, DepthAndNormalLayersRoundTripExactly) {
    Image image = ramp(7, 4);
    image.add_layers();
    for (std::size_t i = 0; i < image.depth.size(); i += 2) {
        image.depth[i] = 3.0f + static_cast<float>(i) * 0.01f;
        image.normals[i] = {0.6f, -0.8f, static_cast<float>(i) * 1e-3f};
    }
    const Image decoded = decode_exr(encode_exr(image));
    ASSERT_TRUE(decoded.has_layers());
    for (std::size_t i = 0; i < image.depth.size(); ++i) {
        EXPECT_TRUE(same_bits(decoded.depth[i], image.depth[i])) << i;
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(same_bits(decoded.normals[i][c], image.normals[i][c])) << i;
    }
    EXPECT_EQ(decoded.depth[1], std::numeric_limits<float>::infinity());  // a miss stays at +∞
}

TEST(Exr, WrittenByExtensionAndReadBack) {
    const test::TempDir dir;
    Image image = ramp(3, 2);
    image.add_layers();
    image.depth[0] = 2.5f;
    write_image(image, dir / "out.EXR");
    const Image decoded = read_exr(dir / "out.EXR");
    EXPECT_EQ(decoded.depth[0], 2.5f);
    EXPECT_EQ(decoded.at(2, 1).x, image.at(2, 1).x);
}

TEST(Exr, MalformedImagesAndDataAreClearErrors) {
    Image inconsistent = ramp(3, 2);
    inconsistent.depth.resize(5);
    inconsistent.normals.resize(6);
    EXPECT_THROW(encode_exr(inconsistent), std::invalid_argument);
    const std::vector<std::uint8_t> garbage = {'n', 'o', 't', ' ', 'e', 'x', 'r'};
    EXPECT_THROW(decode_exr(garbage), std::runtime_error);
    std::vector<std::uint8_t> truncated = encode_exr(ramp(16, 16));
    truncated.resize(truncated.size() / 2);
    EXPECT_THROW(decode_exr(truncated), std::runtime_error);
}

TEST(ImageOutputCheck, RefusesBadNamesAndPlacesAndLeavesNothing) {
    const test::TempDir dir;
    EXPECT_NO_THROW(check_image_output(dir / "fine.exr"));
    EXPECT_THROW(check_image_output(dir / "bad.jpg"), ImageWriteError);
    EXPECT_THROW(check_image_output(dir / "missing" / "x.png"), ImageWriteError);
    std::filesystem::create_directory(dir / "taken.png");
    EXPECT_THROW(check_image_output(dir / "taken.png"), ImageWriteError);
    EXPECT_EQ(dir.entries().size(), 1u);  // only the directory made above: no probe file stays
}

TEST(ImageFormatNames, NamesAndExtensionsAgree) {
    EXPECT_EQ(image_format_from_name("EXR"), ImageFormat::Exr);
    EXPECT_EQ(image_format_for("a/b.Png"), ImageFormat::Png);
    EXPECT_FALSE(image_format_from_name("jpg"));
    EXPECT_FALSE(image_format_for("noext"));
    EXPECT_FALSE(image_format_for("dot."));
}

}  // namespace
}  // namespace zeroset
