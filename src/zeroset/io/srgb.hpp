// The sRGB transfer function (IEC 61966-2-1): the renderer works in linear
// light, 8-bit files (PNG, PPM) and displays expect sRGB-encoded values.
// This is the piecewise curve (linear toe below 0.0031308), not a 2.2 gamma.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace zeroset {

/// Linear light in [0, 1] → sRGB-encoded value in [0, 1]. Input is clamped;
/// NaN maps to 0.
inline double linear_to_srgb(double linear) {
    if (!(linear > 0.0)) return 0.0;  // also catches NaN
    if (linear >= 1.0) return 1.0;
    if (linear <= 0.0031308) return 12.92 * linear;
    return 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

/// sRGB-encoded value in [0, 1] → linear light in [0, 1]. Input is clamped;
/// NaN maps to 0.
inline double srgb_to_linear(double encoded) {
    if (!(encoded > 0.0)) return 0.0;
    if (encoded >= 1.0) return 1.0;
    if (encoded <= 0.04045) return encoded / 12.92;
    return std::pow((encoded + 0.055) / 1.055, 2.4);
}

/// Linear light → 8-bit sRGB code by the formula: clamp to [0, 1], encode,
/// round to nearest. The reference for encode_srgb8.
inline std::uint8_t encode_srgb8_by_formula(float linear) {
    return static_cast<std::uint8_t>(linear_to_srgb(static_cast<double>(linear)) * 255.0 + 0.5);
}

/// For each code c, the smallest float that encode_srgb8_by_formula takes to
/// c or above (0 for code 0), worked out once by bisection over the floats.
const std::array<float, 256>& srgb8_thresholds();

/// Linear light → 8-bit sRGB code, exactly as encode_srgb8_by_formula but by
/// a search of the thresholds: eight comparisons instead of a pow, which
/// took a fifth of the time of rendering a small scene and writing it.
inline std::uint8_t encode_srgb8(float linear) {
    if (!(linear > 0.0f)) return 0;  // also catches NaN
    if (linear >= 1.0f) return 255;
    const std::array<float, 256>& at_least = srgb8_thresholds();
    unsigned code = 0;
    for (unsigned step = 128; step > 0; step >>= 1)
        if (at_least[code + step] <= linear) code += step;
    return static_cast<std::uint8_t>(code);
}

/// 8-bit sRGB code → linear light (the inverse of encode_srgb8 on its codes:
/// encode_srgb8(decode_srgb8(c)) == c for every c).
inline float decode_srgb8(std::uint8_t code) {
    return static_cast<float>(srgb_to_linear(static_cast<double>(code) / 255.0));
}

}  // namespace zeroset
