// Saving a rendered Image: the format comes from the file extension (or is
// named, for standard output), and the file is replaced atomically, so a
// failed render or write never leaves a half-written image. Programs call
// check_image_output() before rendering, so that a bad name or an unwritable
// place is reported before any time is spent.
#pragma once

#include <filesystem>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "zeroset/io/path_error.hpp"
#include "zeroset/render/image.hpp"

namespace zeroset {

/// An image could not be written; the message is "<path>: <reason>", e.g.
/// "out.png: cannot create file: No such file or directory".
class ImageWriteError : public PathError {
public:
    using PathError::PathError;
};

enum class ImageFormat {
    Png,  // 8-bit sRGB RGB with an sRGB chunk
    Ppm,  // binary P6, 8-bit sRGB
    Pfm,  // linear 32-bit float RGB
    Exr,  // OpenEXR, linear 32-bit float RGB, plus Z and N.xyz when the image has layers
};

/// The format for a name: "png", "ppm", "pfm" or "exr" (any case).
std::optional<ImageFormat> image_format_from_name(const std::string& name);

/// The format for a file name by its extension (.png, .ppm, .pfm, .exr;
/// any case), or nothing if the extension is missing or unsupported.
std::optional<ImageFormat> image_format_for(const std::filesystem::path& path);

/// Why `path` cannot be written as an image ("unsupported image format
/// '.jpg' (use .png, .ppm, .pfm or .exr)"), or nothing if its extension is fine.
std::optional<std::string> image_format_problem(const std::filesystem::path& path);

/// Throws ImageWriteError unless an image could be written at `path` now:
/// a supported extension, an existing directory the program may create
/// files in, and no directory of that name. It creates and removes a
/// temporary file there, the surest test.
void check_image_output(const std::filesystem::path& path);

/// `image` in `format`'s bytes. Throws std::invalid_argument for a malformed
/// image, std::runtime_error when the encoder fails.
std::vector<std::uint8_t> encode_image(const Image& image, ImageFormat format);

/// Encodes `image` in the format chosen by `path`'s extension and replaces
/// `path` atomically. Throws ImageWriteError (unsupported extension, empty
/// or inconsistent image, I/O failure); on failure neither the target nor a
/// temporary file is left changed or behind.
void write_image(const Image& image, const std::filesystem::path& path);

/// Encodes `image` in `format` and writes it to standard output. Throws
/// ImageWriteError naming "<stdout>" on failure.
void write_image_to_stdout(const Image& image, ImageFormat format);

}  // namespace zeroset
