// Reading images back, for golden-image and round-trip tests: PNG decoded to
// linear light (inverse sRGB), PFM as stored.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "zeroset/render/image.hpp"

namespace zeroset {

/// An image could not be read; the message is "<path>: <reason>".
class ImageReadError : public std::runtime_error {
public:
    ImageReadError(const std::filesystem::path& path, const std::string& reason)
        : std::runtime_error(path.string() + ": " + reason), path_(path), reason_(reason) {}
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }
    [[nodiscard]] const std::string& reason() const { return reason_; }

private:
    std::filesystem::path path_;
    std::string reason_;
};

/// Any PNG → linear RGB (samples treated as sRGB; alpha dropped).
/// Throws ImageReadError.
Image read_png(const std::filesystem::path& path);

/// A colour or greyscale PFM → RGB floats, row 0 at the top. Throws ImageReadError.
Image read_pfm(const std::filesystem::path& path);

}  // namespace zeroset
