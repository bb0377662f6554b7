// write_image: pick the encoder by extension, encode in memory, then hand the
// bytes to AtomicFile. Encoding first means an encoder failure never touches
// the file system at all.
#include "zeroset/io/image_writer.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <system_error>
#include <vector>

#include "zeroset/io/atomic_file.hpp"
#include "zeroset/io/exr.hpp"
#include "zeroset/io/image_shape.hpp"
#include "zeroset/io/lowercase.hpp"
#include "zeroset/io/pfm.hpp"
#include "zeroset/io/png.hpp"
#include "zeroset/io/ppm.hpp"

namespace zeroset {

namespace {

constexpr const char* supported_formats = "use .png, .ppm, .pfm or .exr";

/// Encodes, turning the encoders' exceptions into ImageWriteError for `where`.
std::vector<std::uint8_t> encode_for(const Image& image, ImageFormat format, const std::filesystem::path& where) {
    try {
        return encode_image(image, format);
    } catch (const std::invalid_argument& e) {
        throw ImageWriteError(where, e.what());
    } catch (const std::runtime_error& e) {
        throw ImageWriteError(where, std::string("cannot encode image: ") + e.what());
    }
}

}  // namespace

std::optional<ImageFormat> image_format_from_name(const std::string& name) {
    const std::string lower = lowercase_ascii(name);
    if (lower == "png") return ImageFormat::Png;
    if (lower == "ppm") return ImageFormat::Ppm;
    if (lower == "pfm") return ImageFormat::Pfm;
    if (lower == "exr") return ImageFormat::Exr;
    return std::nullopt;
}

std::optional<ImageFormat> image_format_for(const std::filesystem::path& path) {
    const std::string extension = path.extension().string();
    if (extension.size() < 2) return std::nullopt;
    return image_format_from_name(extension.substr(1));
}

std::optional<std::string> image_format_problem(const std::filesystem::path& path) {
    if (image_format_for(path)) return std::nullopt;
    const std::string extension = path.extension().string();
    if (extension.empty() || extension == ".")
        return std::string("no file extension to choose the image format (") + supported_formats + ")";
    return "unsupported image format '" + extension + "' (" + supported_formats + ")";
}

void check_image_output(const std::filesystem::path& path) {
    if (const auto problem = image_format_problem(path)) throw ImageWriteError(path, *problem);
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) throw ImageWriteError(path, "is a directory");
    try {
        const AtomicFile probe(path);  // created now, removed when it goes out of scope
    } catch (const FileWriteError& e) {
        throw ImageWriteError(path, e.reason());
    }
}

std::vector<std::uint8_t> encode_image(const Image& image, ImageFormat format) {
    require_valid_image(image);
    switch (format) {
        case ImageFormat::Png: return encode_png(image);
        case ImageFormat::Ppm: return encode_ppm(image);
        case ImageFormat::Pfm: return encode_pfm(image);
        case ImageFormat::Exr: return encode_exr(image);
    }
    throw std::invalid_argument("unknown image format");
}

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::optional<ImageFormat> format = image_format_for(path);
    if (!format) throw ImageWriteError(path, *image_format_problem(path));
    const std::vector<std::uint8_t> bytes = encode_for(image, *format, path);
    try {
        write_file_atomically(path, bytes);
    } catch (const FileWriteError& e) {
        throw ImageWriteError(path, e.reason());
    }
}

void write_image_to_stdout(const Image& image, ImageFormat format) {
    const std::filesystem::path name = "<stdout>";
    const std::vector<std::uint8_t> bytes = encode_for(image, format, name);
    errno = 0;
    if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
        throw ImageWriteError(name, "cannot write: " + std::generic_category().message(errno ? errno : EIO));
}

}  // namespace zeroset
