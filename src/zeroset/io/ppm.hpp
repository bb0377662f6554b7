// Binary PPM (P6): the simplest 8-bit image file, readable by everything
// (netpbm, ImageMagick, most viewers) and trivial to inspect in tests.
#pragma once

#include <cstdint>
#include <vector>

#include "zeroset/render/image.hpp"

namespace zeroset {

/// "P6\n<w> <h>\n255\n" then sRGB-encoded 8-bit RGB, top row first.
/// Throws std::invalid_argument for a malformed image.
std::vector<std::uint8_t> encode_ppm(const Image& image);

}  // namespace zeroset
