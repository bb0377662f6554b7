// PFM (Portable Float Map): linear-light 32-bit floats with no quantisation
// and no transfer curve — exact render output for debugging, HDR tools and
// golden-image comparisons.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "zeroset/render/image.hpp"

namespace zeroset {

/// "PF\n<w> <h>\n-1.0\n" then little-endian float RGB, bottom row first (as
/// the format requires). Values are stored as they are, NaN and ∞ included.
/// Throws std::invalid_argument for a malformed image.
std::vector<std::uint8_t> encode_pfm(const Image& image);

/// Decodes colour ("PF") or greyscale ("Pf", replicated to RGB) PFM of either
/// byte order. The scale's magnitude is ignored. Throws std::runtime_error
/// for malformed or truncated data.
Image decode_pfm(std::span<const std::uint8_t> bytes);

}  // namespace zeroset
