// PFM: exact header and byte layout (little-endian, bottom row first), exact
// round trips including non-finite values, and the decoder's error paths.
#include "zeroset/io/pfm.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "zeroset/io/image_reader.hpp"
#include "zeroset/io/image_writer.hpp"
#include "support/temp_dir.hpp"

namespace zeroset {
namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes text_bytes(const std::string& text) { return {text.begin(), text.end()}; }

void append(Bytes& out, std::initializer_list<std::uint8_t> bytes) { out.insert(out.end(), bytes); }

bool same_bits(float a, float b) { return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b); }

TEST(Pfm, HeaderAndLayout) {
    Image image(2, 3);
    image.at(0, 2) = {1.0f, -2.0f, 0.5f};  // bottom-left: stored first
    image.at(1, 0) = {0.0f, 0.0f, 3.0f};   // top-right: stored last
    const Bytes bytes = encode_pfm(image);
    const std::string header = "PF\n2 3\n-1.0\n";
    ASSERT_EQ(bytes.size(), header.size() + 2 * 3 * 12);
    EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(header.size())), header);
    const std::uint8_t* data = bytes.data() + header.size();
    const std::uint8_t first[12] = {0x00, 0x00, 0x80, 0x3F, 0x00, 0x00, 0x00, 0xC0, 0x00, 0x00, 0x00, 0x3F};
    EXPECT_EQ(0, std::memcmp(data, first, 12));
    const std::uint8_t last[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0x00, 0x00, 0x40, 0x40};
    EXPECT_EQ(0, std::memcmp(data + 5 * 12, last, 12));
}

TEST(Pfm, RoundTripIsExact) {
    Image image(4, 3);
    float v = -1.25f;
    for (Vec3f& p : image.pixels) {
        p = {v, v * 3.5f, 1.0f / (v + 10.0f)};
        v += 0.37f;
    }
    image.at(0, 0) = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                      -std::numeric_limits<float>::infinity()};
    image.at(3, 2) = {std::numeric_limits<float>::denorm_min(), -0.0f, 1e30f};

    const Image decoded = decode_pfm(encode_pfm(image));
    ASSERT_EQ(decoded.width, 4);
    ASSERT_EQ(decoded.height, 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c)
            EXPECT_TRUE(same_bits(decoded.pixels[i][c], image.pixels[i][c])) << "pixel " << i << " channel " << c;

    const test::TempDir dir;
    write_image(image, dir / "out.PFM");
    EXPECT_EQ(test::read_bytes(dir / "out.PFM"), encode_pfm(image));
    const Image from_file = read_pfm(dir / "out.PFM");
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(same_bits(from_file.pixels[i][c], image.pixels[i][c]));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.PFM"});
}

TEST(Pfm, DecodesBigEndianAndGreyscale) {
    // 1×2 colour, big-endian (positive scale); bottom row (stored first) is 1, 2, 0.5.
    Bytes big = text_bytes("PF 1 2 1.0\n");
    append(big, {0x3F, 0x80, 0x00, 0x00, 0x40, 0x00, 0x00, 0x00, 0x3F, 0x00, 0x00, 0x00});
    append(big, {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0, 0x40, 0x00, 0x00});
    const Image colour = decode_pfm(big);
    ASSERT_EQ(colour.width, 1);
    ASSERT_EQ(colour.height, 2);
    EXPECT_EQ(colour.at(0, 1), Vec3f(1.0f, 2.0f, 0.5f));
    EXPECT_EQ(colour.at(0, 0), Vec3f(0.0f, 0.0f, -3.0f));

    // 2×1 greyscale, little-endian, extra whitespace in the header.
    Bytes grey = text_bytes("Pf\n2   1\n-4.0\n");
    append(grey, {0x00, 0x00, 0x80, 0x3E, 0x00, 0x00, 0x20, 0x41});
    const Image g = decode_pfm(grey);
    ASSERT_EQ(g.width, 2);
    EXPECT_EQ(g.at(0, 0), Vec3f(0.25f, 0.25f, 0.25f));
    EXPECT_EQ(g.at(1, 0), Vec3f(10.0f, 10.0f, 10.0f));
}

void expect_rejected(const Bytes& bytes, const std::string& reason) {
    try {
        decode_pfm(bytes);
        FAIL() << "accepted; expected: " << reason;
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
}

TEST(Pfm, RejectsMalformedData) {
    expect_rejected(text_bytes(""), "missing magic number");
    expect_rejected(text_bytes("P6\n1 1\n255\nabc"), "not a PFM file");
    expect_rejected(text_bytes("PF\n1"), "missing height");
    expect_rejected(text_bytes("PF\n0 1\n-1.0\n"), "invalid PFM: size 0x1");
    expect_rejected(text_bytes("PF\n-2 1\n-1.0\n"), "invalid PFM: size -2x1");
    expect_rejected(text_bytes("PF\n1x 1\n-1.0\n"), "bad width '1x'");
    expect_rejected(text_bytes("PF\n99999999999 1\n-1.0\n"), "bad width");
    expect_rejected(text_bytes("PF\n1 1\n0\n"), "scale must be finite and non-zero");
    expect_rejected(text_bytes("PF\n1 1\n-1.0"), "no whitespace after the scale");
    expect_rejected(text_bytes("PF\n1 1\n-1.0\n12345678901"), "truncated");
    expect_rejected(text_bytes("PF\n2000000000 2000000000\n-1.0\n"), "truncated");
    expect_rejected(text_bytes("PF\n1 1\n-1.0\n1234567890123"), "unexpected data after the pixels");
}

TEST(Pfm, RejectsMalformedImages) {
    EXPECT_THROW(encode_pfm(Image(0, 5)), std::invalid_argument);
    Image wrong(2, 2);
    wrong.pixels.push_back({});
    EXPECT_THROW(encode_pfm(wrong), std::invalid_argument);
}

TEST(Pfm, ReadErrorNamesThePath) {
    const test::TempDir dir;
    test::write_text(dir / "bad.pfm", "PF\n1 1\n-1.0\n");
    try {
        read_pfm(dir / "bad.pfm");
        FAIL();
    } catch (const ImageReadError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "bad.pfm").string() + ": invalid PFM: truncated pixel data");
    }
}

}  // namespace
}  // namespace zeroset
