// OpenEXR: linear half-free float RGB, plus the depth (Z) and normal
// (N.x, N.y, N.z) layers when the image carries them — the format compositors
// and HDR tools open, and POV-Ray writes. Encoded in memory, so the file
// itself is written atomically like every other image.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "zeroset/render/image.hpp"

namespace zeroset {

/// A scan-line EXR with 32-bit float channels R, G, B, and Z, N.x, N.y, N.z
/// when `image` has depth and normals; ZIP compression. Throws
/// std::invalid_argument for a malformed image.
std::vector<std::uint8_t> encode_exr(const Image& image);

/// Reads an EXR's R, G, B (missing channels read as 0) and, when present,
/// Z and N.x, N.y, N.z. Throws std::runtime_error for malformed data.
Image decode_exr(std::span<const std::uint8_t> bytes);

}  // namespace zeroset
