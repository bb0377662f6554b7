// PPM (P6): header and every byte checked by hand.
#include "zeroset/io/ppm.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "zeroset/io/image_writer.hpp"
#include "support/temp_dir.hpp"

namespace zeroset {
namespace {

TEST(Ppm, HeaderAndBytesTopRowFirst) {
    Image image(2, 2);
    image.at(0, 0) = {1.0f, 0.0f, 0.5f};
    image.at(1, 0) = {0.0031308f, 2.0f, -1.0f};
    image.at(0, 1) = {0.18f, 0.18f, 0.18f};
    image.at(1, 1) = {0.2158605f, 0.001f, 1.0f};

    const std::string header = "P6\n2 2\n255\n";
    std::vector<std::uint8_t> expected(header.begin(), header.end());
    expected.insert(expected.end(), {255, 0, 188, 10, 255, 0, 118, 118, 118, 128, 3, 255});
    EXPECT_EQ(encode_ppm(image), expected);

    const test::TempDir dir;
    write_image(image, dir / "out.ppm");
    EXPECT_EQ(test::read_bytes(dir / "out.ppm"), expected);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.ppm"});
}

TEST(Ppm, NonSquareHeaderIsWidthThenHeight) {
    const std::vector<std::uint8_t> bytes = encode_ppm(Image(3, 1));
    const std::string header = "P6\n3 1\n255\n";
    ASSERT_EQ(bytes.size(), header.size() + 9);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(header.size())), header);
}

TEST(Ppm, RejectsMalformedImages) {
    EXPECT_THROW(encode_ppm(Image()), std::invalid_argument);
    Image wrong(2, 2);
    wrong.pixels.pop_back();
    EXPECT_THROW(encode_ppm(wrong), std::invalid_argument);
}

}  // namespace
}  // namespace zeroset
