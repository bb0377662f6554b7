// The sRGB transfer function against the published curve (IEC 61966-2-1).
#include "zeroset/io/srgb.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace zeroset {
namespace {

TEST(Srgb, EncodesKnownValues) {
    EXPECT_EQ(encode_srgb8(0.0f), 0);
    EXPECT_EQ(encode_srgb8(1.0f), 255);
    EXPECT_EQ(encode_srgb8(0.5f), 188);  // 1.055·0.5^(1/2.4) − 0.055 = 0.73536 → 187.52
    EXPECT_EQ(encode_srgb8(0.18f), 118);  // middle grey: 0.46135 → 117.64
    EXPECT_EQ(encode_srgb8(0.2158605f), 128);
}

TEST(Srgb, IsNotAPureGamma) {
    // The linear toe: 12.92·0.001·255 = 3.29; a 2.2 gamma would give 11.
    EXPECT_EQ(encode_srgb8(0.001f), 3);
    EXPECT_DOUBLE_EQ(linear_to_srgb(0.002), 12.92 * 0.002);
    EXPECT_NEAR(srgb_to_linear(0.02), 0.02 / 12.92, 1e-15);
}

TEST(Srgb, BranchesMeetAtTheBoundary) {
    const double below = linear_to_srgb(0.0031308);
    const double above = linear_to_srgb(std::nextafter(0.0031308, 1.0));
    EXPECT_NEAR(below, 0.04044994, 1e-8);
    EXPECT_NEAR(above, below, 1e-6);
    EXPECT_EQ(encode_srgb8(0.0031308f), 10);  // 0.04045·255 = 10.31
    EXPECT_NEAR(srgb_to_linear(0.04045), 0.0031308, 1e-7);
    EXPECT_NEAR(srgb_to_linear(std::nextafter(0.04045, 1.0)), 0.0031308, 1e-7);
}

TEST(Srgb, ClampsOutOfRangeAndNonFinite) {
    EXPECT_EQ(encode_srgb8(-0.5f), 0);
    EXPECT_EQ(encode_srgb8(7.0f), 255);
    EXPECT_EQ(encode_srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(encode_srgb8(std::numeric_limits<float>::infinity()), 255);
    EXPECT_EQ(encode_srgb8(-std::numeric_limits<float>::infinity()), 0);
}

TEST(Srgb, TheThresholdSearchAgreesWithTheFormula) {
    // Everywhere near a code's threshold, where a slip would show, and on a
    // sweep over all of [0, 1].
    const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
    int checked = 0;
    for (unsigned code = 1; code < 256; ++code) {
        const std::uint32_t at = bits(srgb8_thresholds()[code]);
        EXPECT_EQ(encode_srgb8_by_formula(srgb8_thresholds()[code]), code);
        EXPECT_EQ(encode_srgb8_by_formula(std::bit_cast<float>(at - 1)), code - 1);
        for (std::uint32_t b = at - 300; b <= at + 300 && b <= bits(1.0f); ++b, ++checked) {
            const float f = std::bit_cast<float>(b);
            ASSERT_EQ(encode_srgb8(f), encode_srgb8_by_formula(f)) << f;
        }
    }
    for (std::uint32_t b = 0; b <= bits(1.0f); b += 1009, ++checked) {
        const float f = std::bit_cast<float>(b);
        ASSERT_EQ(encode_srgb8(f), encode_srgb8_by_formula(f)) << f;
    }
    EXPECT_GT(checked, 1000000);
}

TEST(Srgb, DecodesKnownValues) {
    EXPECT_EQ(decode_srgb8(0), 0.0f);
    EXPECT_EQ(decode_srgb8(255), 1.0f);
    EXPECT_NEAR(decode_srgb8(128), 0.2158605f, 1e-6f);
    EXPECT_NEAR(decode_srgb8(188), 0.5028865f, 1e-6f);
    EXPECT_NEAR(decode_srgb8(10), 10.0f / 255.0f / 12.92f, 1e-9f);
}

TEST(Srgb, DecodeThenEncodeIsIdentityOnEveryCode) {
    for (int code = 0; code <= 255; ++code)
        EXPECT_EQ(encode_srgb8(decode_srgb8(static_cast<std::uint8_t>(code))), code) << "code " << code;
}

TEST(Srgb, EncodeIsMonotoneAndInvertible) {
    int previous = 0;
    for (int i = 0; i <= 100000; ++i) {
        const double v = i / 100000.0;
        const int code = encode_srgb8(static_cast<float>(v));
        EXPECT_GE(code, previous);
        previous = code;
        EXPECT_NEAR(srgb_to_linear(linear_to_srgb(v)), v, 1e-12);
    }
}

}  // namespace
}  // namespace zeroset
