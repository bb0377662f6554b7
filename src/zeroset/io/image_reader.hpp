// Reading images back, for golden-image and round-trip tests: PNG decoded to
// linear light (inverse sRGB), PFM and EXR as stored.
#pragma once

#include <filesystem>
#include <string>

#include "zeroset/io/path_error.hpp"
#include "zeroset/render/image.hpp"

namespace zeroset {

/// An image could not be read; the message is "<path>: <reason>".
class ImageReadError : public PathError {
public:
    using PathError::PathError;
};

/// Any PNG → linear RGB (samples treated as sRGB; alpha dropped).
/// Throws ImageReadError.
Image read_png(const std::filesystem::path& path);

/// A colour or greyscale PFM → RGB floats, row 0 at the top. Throws ImageReadError.
Image read_pfm(const std::filesystem::path& path);

/// An EXR's RGB, and its Z and N.xyz layers when present. Throws ImageReadError.
Image read_exr(const std::filesystem::path& path);

}  // namespace zeroset
