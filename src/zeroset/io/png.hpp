// PNG encoding and decoding in memory, through libpng. Files are written
// as 8-bit sRGB RGB with sRGB/gAMA/cHRM chunks so viewers show them as the
// renderer meant; decoding returns linear light for golden-image tests.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "zeroset/render/image.hpp"

namespace zeroset {

/// The PNG file for `image`: 8-bit RGB, sRGB-encoded (clamped to [0, 1],
/// rounded to nearest). Throws std::invalid_argument for a malformed image,
/// std::runtime_error when libpng fails (message from libpng).
std::vector<std::uint8_t> encode_png(const Image& image);

/// Decodes any PNG (palette, grey, 16-bit, alpha, interlaced) to linear RGB,
/// treating its samples as sRGB (gamma chunks are ignored) and dropping
/// alpha. Throws std::runtime_error for data that is not a valid PNG.
Image decode_png(std::span<const std::uint8_t> bytes);

}  // namespace zeroset
