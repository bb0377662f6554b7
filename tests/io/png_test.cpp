// PNG: the decoder against hand-built files (an oracle independent of our
// encoder), then the encoder through the decoder, chunk layout, and libpng
// failures turned into exceptions without leaks.
#include "zeroset/io/png.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "zeroset/io/image_reader.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/io/srgb.hpp"
#include "support/temp_dir.hpp"

namespace zeroset {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (std::size_t i = 0; i < size; ++i) {
        crc ^= data[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

void put_u32_be(Bytes& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

std::uint32_t get_u32_be(const std::uint8_t* p) {
    return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

void put_chunk(Bytes& out, const char* type, const Bytes& data) {
    put_u32_be(out, static_cast<std::uint32_t>(data.size()));
    Bytes typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    out.insert(out.end(), typed.begin(), typed.end());
    put_u32_be(out, crc32(typed.data(), typed.size()));
}

// A zlib stream holding `raw` in one stored (uncompressed) deflate block.
Bytes zlib_stored(const Bytes& raw) {
    Bytes out{0x78, 0x01, 0x01};
    const auto len = static_cast<std::uint16_t>(raw.size());
    const auto nlen = static_cast<std::uint16_t>(~len);
    out.insert(out.end(), {static_cast<std::uint8_t>(len), static_cast<std::uint8_t>(len >> 8),
                           static_cast<std::uint8_t>(nlen), static_cast<std::uint8_t>(nlen >> 8)});
    out.insert(out.end(), raw.begin(), raw.end());
    std::uint32_t a = 1, b = 0;
    for (std::uint8_t byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    put_u32_be(out, (b << 16) | a);
    return out;
}

// A PNG built by hand: `rows` are the raw scanlines, filter byte included.
Bytes hand_made_png(std::uint32_t width, std::uint32_t height, std::uint8_t bit_depth, std::uint8_t colour_type,
                    const Bytes& rows) {
    Bytes png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    Bytes ihdr;
    put_u32_be(ihdr, width);
    put_u32_be(ihdr, height);
    ihdr.insert(ihdr.end(), {bit_depth, colour_type, 0, 0, 0});
    put_chunk(png, "IHDR", ihdr);
    put_chunk(png, "IDAT", zlib_stored(rows));
    put_chunk(png, "IEND", {});
    return png;
}

struct Chunk {
    std::string type;
    Bytes data;
};

std::vector<Chunk> chunks_of(const Bytes& png) {
    std::vector<Chunk> chunks;
    std::size_t pos = 8;
    while (pos + 12 <= png.size()) {
        const std::uint32_t length = get_u32_be(&png[pos]);
        Chunk chunk{std::string(reinterpret_cast<const char*>(&png[pos + 4]), 4),
                    Bytes(png.begin() + static_cast<std::ptrdiff_t>(pos + 8),
                          png.begin() + static_cast<std::ptrdiff_t>(pos + 8 + length))};
        EXPECT_EQ(get_u32_be(&png[pos + 8 + length]), crc32(&png[pos + 4], length + 4)) << chunk.type;
        chunks.push_back(std::move(chunk));
        pos += 12 + length;
    }
    EXPECT_EQ(pos, png.size());
    return chunks;
}

Image test_pattern(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = {static_cast<float>(x) / static_cast<float>(width - 1),
                              static_cast<float>(y) / static_cast<float>(height - 1),
                              static_cast<float>((x * 7 + y * 13) % 17) / 16.0f};
    image.at(0, 0) = {-0.5f, 2.0f, std::numeric_limits<float>::quiet_NaN()};
    image.at(1, 0) = {0.5f, 0.0031308f, 1e-5f};
    return image;
}

TEST(PngDecode, ReadsHandMadeRgb8) {
    // 2×2 RGB: top row red, mid-grey (code 188); bottom row black, white.
    const Bytes png = hand_made_png(2, 2, 8, 2, {0, 255, 0, 0, 188, 188, 188, 0, 0, 0, 0, 255, 255, 255});
    const Image image = decode_png(png);
    ASSERT_EQ(image.width, 2);
    ASSERT_EQ(image.height, 2);
    EXPECT_EQ(image.at(0, 0), Vec3f(1.0f, 0.0f, 0.0f));
    EXPECT_NEAR(image.at(1, 0).x, 0.5028865f, 1e-6f);
    EXPECT_EQ(image.at(0, 1), Vec3f(0.0f, 0.0f, 0.0f));
    EXPECT_EQ(image.at(1, 1), Vec3f(1.0f, 1.0f, 1.0f));
}

TEST(PngDecode, ExpandsGreyAndScales16Bit) {
    // 3×1 grey, 8-bit, with a Sub filter on the row: raw 10, 10+20, 30+98.
    const Image grey = decode_png(hand_made_png(3, 1, 8, 0, {1, 10, 20, 98}));
    ASSERT_EQ(grey.width, 3);
    EXPECT_EQ(grey.at(0, 0), Vec3f(decode_srgb8(10), decode_srgb8(10), decode_srgb8(10)));
    EXPECT_EQ(grey.at(1, 0).y, decode_srgb8(30));
    EXPECT_EQ(grey.at(2, 0).z, decode_srgb8(128));

    // 1×1 RGB, 16-bit: 0xFFFF, 0x0000, 0xBCBC = 188·257 → 8-bit codes 255, 0, 188.
    const Image deep = decode_png(hand_made_png(1, 1, 16, 2, {0, 0xFF, 0xFF, 0x00, 0x00, 0xBC, 0xBC}));
    EXPECT_EQ(deep.at(0, 0), Vec3f(1.0f, 0.0f, decode_srgb8(188)));
}

TEST(PngDecode, RejectsBadData) {
    EXPECT_THROW(decode_png(Bytes{1, 2, 3}), std::runtime_error);
    EXPECT_THROW(decode_png(Bytes(100, 0)), std::runtime_error);

    const Bytes good = encode_png(test_pattern(16, 16));
    for (std::size_t cut : {std::size_t{8}, std::size_t{20}, std::size_t{40}, good.size() / 2, good.size() - 13}) {
        const Bytes truncated(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(cut));
        EXPECT_THROW(decode_png(truncated), std::runtime_error) << "cut at " << cut;
    }

    Bytes corrupt = good;
    corrupt[20] ^= 0x40;  // inside IHDR: its CRC no longer matches
    try {
        decode_png(corrupt);
        FAIL() << "corrupt IHDR accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("invalid PNG"), std::string::npos) << e.what();
    }
}

TEST(PngEncode, WritesRgb8WithSrgbChunks) {
    const Bytes png = encode_png(test_pattern(5, 3));
    ASSERT_GE(png.size(), 8u);
    EXPECT_EQ(0, std::memcmp(png.data(), "\x89PNG\r\n\x1a\n", 8));
    const std::vector<Chunk> chunks = chunks_of(png);
    ASSERT_GE(chunks.size(), 5u);
    EXPECT_EQ(chunks.front().type, "IHDR");
    EXPECT_EQ(chunks.back().type, "IEND");
    const Bytes& ihdr = chunks.front().data;
    ASSERT_EQ(ihdr.size(), 13u);
    EXPECT_EQ(get_u32_be(&ihdr[0]), 5u);
    EXPECT_EQ(get_u32_be(&ihdr[4]), 3u);
    EXPECT_EQ(ihdr[8], 8);   // bit depth
    EXPECT_EQ(ihdr[9], 2);   // colour type RGB
    EXPECT_EQ(ihdr[12], 0);  // not interlaced

    bool srgb = false, gama = false, idat_seen = false;
    for (const Chunk& chunk : chunks) {
        if (chunk.type == "IDAT") idat_seen = true;
        if (chunk.type == "sRGB") {
            EXPECT_FALSE(idat_seen) << "sRGB must precede IDAT";
            ASSERT_EQ(chunk.data.size(), 1u);
            EXPECT_EQ(chunk.data[0], 0);  // perceptual intent
            srgb = true;
        }
        if (chunk.type == "gAMA") {
            EXPECT_FALSE(idat_seen);
            ASSERT_EQ(chunk.data.size(), 4u);
            EXPECT_EQ(get_u32_be(chunk.data.data()), 45455u);  // 1/2.2, as the PNG spec pairs with sRGB
            gama = true;
        }
    }
    EXPECT_TRUE(srgb);
    EXPECT_TRUE(gama);
}

TEST(PngEncode, RoundTripsToTheQuantisedInput) {
    const Image original = test_pattern(37, 23);
    const Image decoded = decode_png(encode_png(original));
    ASSERT_EQ(decoded.width, original.width);
    ASSERT_EQ(decoded.height, original.height);
    for (int y = 0; y < original.height; ++y) {
        for (int x = 0; x < original.width; ++x) {
            for (int c = 0; c < 3; ++c) {
                const float in = original.at(x, y)[c];
                const float out = decoded.at(x, y)[c];
                // Re-encoding gives back exactly the code that was written…
                EXPECT_EQ(encode_srgb8(out), encode_srgb8(in)) << x << "," << y << " channel " << c;
                // …and in sRGB space the value is within half a step of the clamped input.
                const double clamped = std::isnan(in) ? 0.0 : std::fmin(std::fmax(in, 0.0f), 1.0f);
                EXPECT_NEAR(linear_to_srgb(out), linear_to_srgb(clamped), 0.5 / 255 + 1e-6);
            }
        }
    }
}

TEST(PngEncode, FileRoundTripThroughWriteImage) {
    const test::TempDir dir;
    const Image original = test_pattern(8, 6);
    write_image(original, dir / "out.png");
    EXPECT_EQ(test::read_bytes(dir / "out.png"), encode_png(original));
    const Image decoded = read_png(dir / "out.png");
    ASSERT_EQ(decoded.width, 8);
    ASSERT_EQ(decoded.height, 6);
    for (std::size_t i = 0; i < decoded.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(encode_srgb8(decoded.pixels[i][c]), encode_srgb8(original.pixels[i][c]));
}

TEST(PngEncode, LibpngErrorBecomesAnException) {
    // libpng refuses widths over its default limit of 1 000 000; the error
    // comes back through longjmp and must surface as an exception.
    const Image too_wide(1'000'001, 1);
    try {
        encode_png(too_wide);
        FAIL() << "libpng accepted a width over its limit";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("libpng"), std::string::npos) << e.what();
    }
}

TEST(PngRead, MissingOrInvalidFileNamesThePath) {
    const test::TempDir dir;
    try {
        read_png(dir / "missing.png");
        FAIL();
    } catch (const ImageReadError& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "missing.png").string() + ": cannot open file: No such file or directory");
    }
    test::write_text(dir / "text.png", "hello");
    try {
        read_png(dir / "text.png");
        FAIL();
    } catch (const ImageReadError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "text.png").string() + ": not a PNG file");
    }
}

}  // namespace
}  // namespace zeroset
