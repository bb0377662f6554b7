// The sRGB transfer function (IEC 61966-2-1): the renderer works in linear
// light, 8-bit files (PNG, PPM) and displays expect sRGB-encoded values.
// This is the piecewise curve (linear toe below 0.0031308), not a 2.2 gamma.
#pragma once

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

/// Linear light → 8-bit sRGB code: clamp to [0, 1], encode, round to nearest.
inline std::uint8_t encode_srgb8(float linear) {
    return static_cast<std::uint8_t>(linear_to_srgb(static_cast<double>(linear)) * 255.0 + 0.5);
}

/// 8-bit sRGB code → linear light (the inverse of encode_srgb8 on its codes:
/// encode_srgb8(decode_srgb8(c)) == c for every c).
inline float decode_srgb8(std::uint8_t code) {
    return static_cast<float>(srgb_to_linear(static_cast<double>(code) / 255.0));
}

}  // namespace zeroset
