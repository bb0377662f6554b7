// write_image: pick the encoder by extension, encode in memory, then hand the
// bytes to AtomicFile. Encoding first means an encoder failure never touches
// the file system at all.
#include "zeroset/io/image_writer.hpp"

#include <cstdint>
#include <vector>

#include "zeroset/io/atomic_file.hpp"
#include "zeroset/io/image_shape.hpp"
#include "zeroset/io/pfm.hpp"
#include "zeroset/io/png.hpp"
#include "zeroset/io/ppm.hpp"

namespace zeroset {

namespace {

constexpr const char* supported_formats = "use .png, .ppm or .pfm";

std::string lowercase_ascii(std::string text) {
    for (char& c : text)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return text;
}

}  // namespace

std::optional<ImageFormat> image_format_for(const std::filesystem::path& path) {
    const std::string extension = lowercase_ascii(path.extension().string());
    if (extension == ".png") return ImageFormat::Png;
    if (extension == ".ppm") return ImageFormat::Ppm;
    if (extension == ".pfm") return ImageFormat::Pfm;
    return std::nullopt;
}

std::optional<std::string> image_format_problem(const std::filesystem::path& path) {
    if (image_format_for(path)) return std::nullopt;
    const std::string extension = path.extension().string();
    if (extension.empty() || extension == ".")
        return std::string("no file extension to choose the image format (") + supported_formats + ")";
    return "unsupported image format '" + extension + "' (" + supported_formats + ")";
}

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::optional<ImageFormat> format = image_format_for(path);
    if (!format) throw ImageWriteError(path, *image_format_problem(path));

    std::vector<std::uint8_t> bytes;
    try {
        require_valid_image(image);
        switch (*format) {
            case ImageFormat::Png: bytes = encode_png(image); break;
            case ImageFormat::Ppm: bytes = encode_ppm(image); break;
            case ImageFormat::Pfm: bytes = encode_pfm(image); break;
        }
    } catch (const std::invalid_argument& e) {
        throw ImageWriteError(path, e.what());
    } catch (const std::runtime_error& e) {
        throw ImageWriteError(path, std::string("cannot encode image: ") + e.what());
    }

    try {
        write_file_atomically(path, bytes);
    } catch (const FileWriteError& e) {
        throw ImageWriteError(path, e.reason());
    }
}

}  // namespace zeroset
