// Saving a rendered Image: the format comes from the file extension, and the
// file is replaced atomically, so a failed render or write never leaves a
// half-written image. Programs call image_format_for() before rendering to
// reject an unsupported name up front.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

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
};

/// The format for a file name by its extension (.png, .ppm, .pfm; any
/// case), or nothing if the extension is missing or unsupported.
std::optional<ImageFormat> image_format_for(const std::filesystem::path& path);

/// Why `path` cannot be written as an image ("unsupported image format
/// '.jpg' (use .png, .ppm or .pfm)"), or nothing if its extension is fine.
std::optional<std::string> image_format_problem(const std::filesystem::path& path);

/// Encodes `image` in the format chosen by `path`'s extension and replaces
/// `path` atomically. Throws ImageWriteError (unsupported extension, empty
/// or inconsistent image, I/O failure); on failure neither the target nor a
/// temporary file is left changed or behind.
void write_image(const Image& image, const std::filesystem::path& path);

}  // namespace zeroset
